# Sourced by the benchmarks that run configs/dynvo.json and ipl.json: `detector` holds the
# --set overrides for the Yolo-Fastest body model, from data/models/ (tools/fetch_models.sh)
# when fetched, else from ../shared/models; empty when neither has it (dynvo then runs
# geometric only, and its run.json says so). Needs $root and $shared.
models="$root/data/models"
[ -f "$models/yolo-fastest-1.1_body.weights" ] || models="$shared/models"
detector=()
if [ -f "$models/yolo-fastest-1.1_body.weights" ]; then
  detector=(--set "detector.model=$models/yolo-fastest-1.1_body.weights"
            --set "detector.config=$models/yolo-fastest-1.1_body.cfg")
fi
