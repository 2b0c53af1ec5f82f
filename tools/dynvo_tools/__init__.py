"""dynvo's Python tools: runs of dynvo-cli evaluated with rpe/ate, and the tables and figures
made from them. One command line, `python3 -m dynvo_tools COMMAND` (tools/ on PYTHONPATH; the
shell wrappers in tools/ and bench/ build the binaries first and call it):

  suite, suite-table   the benchmark suite's dev and validation splits (bench/suite.sh)
  suite-compare        two suite results CSVs row by row: a change judged (bench/suite.sh compare)
  table1               the paper's Table 1 on the sequences at hand (tools/table1.sh)
  sweep                a parameter sweep over a JSON grid, locally or as a Slurm array (tools/sweep.sh)
  figures              RPE over time, trajectory top view, mask panels (tools/figures.sh)
  feature-budget       accuracy against the ORB budget and RANSAC seeds (bench/feature_budget.sh)
  speed-table, memory-table   the tables of bench/speed.sh and bench/memory.sh
  evaluate             one config on one sequence, run and evaluated: the shared step of all the above
  lists                rgb.txt and depth.txt for a folder of PNGs (tools/make_lists.sh)
  compare              several trajectories against one groundtruth: table and plots (tools/compare.sh)

Every command runs a config through the same helper (evaluation.run_and_evaluate).
"""
