#!/usr/bin/env bash
# Downloads and unpacks TUM RGB-D sequences (default: the 9 of the paper's Table 1) and Bonn
# RGB-D Dynamic sequences.
#   bash tools/fetch_tum.sh [--dest DIR] [SEQUENCE...]
# SEQUENCE names are the folder names: TUM's rgbd_dataset_freiburgN_*, Bonn's rgbd_bonn_*.
# Resumable: partial archives are continued; sequences already unpacked (rgb.txt, depth.txt
# and groundtruth.txt present) are skipped; every archive is checked before unpacking.
set -euo pipefail

dest="data/tum"
sequences=()
while [ $# -gt 0 ]; do
  case "$1" in
    --dest) dest="$2"; shift 2 ;;
    -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
    -*) echo "fetch_tum: error: unknown option '$1' (expected --dest DIR or sequence names)" >&2; exit 2 ;;
    *) sequences+=("$1"); shift ;;
  esac
done
if [ ${#sequences[@]} -eq 0 ]; then
  sequences=(
    rgbd_dataset_freiburg2_desk_with_person
    rgbd_dataset_freiburg3_sitting_halfsphere
    rgbd_dataset_freiburg3_sitting_rpy
    rgbd_dataset_freiburg3_sitting_static
    rgbd_dataset_freiburg3_sitting_xyz
    rgbd_dataset_freiburg3_walking_halfsphere
    rgbd_dataset_freiburg3_walking_rpy
    rgbd_dataset_freiburg3_walking_static
    rgbd_dataset_freiburg3_walking_xyz
  )
fi
# Mirrors of the TUM RGB-D benchmark, tried in order; the Bonn RGB-D Dynamic dataset's site.
mirrors=("https://cvg.cit.tum.de/rgbd/dataset" "https://vision.in.tum.de/rgbd/dataset")
bonn="https://www.ipb.uni-bonn.de/html/projects/rgbd_dynamic2019"
python="${PYTHON:-/usr/bin/python3}"

command -v curl >/dev/null || { echo "fetch_tum: error: curl is required (apt-get install curl)" >&2; exit 1; }
mkdir -p "$dest"

complete() { [ -f "$1/rgb.txt" ] && [ -f "$1/depth.txt" ] && [ -f "$1/groundtruth.txt" ]; }

failed=()
for seq in "${sequences[@]}"; do
  urls=()
  if [[ "$seq" =~ ^rgbd_dataset_freiburg([123])_[a-z0-9_]+$ ]]; then
    archive="$dest/$seq.tgz"
    for mirror in "${mirrors[@]}"; do urls+=("$mirror/freiburg${BASH_REMATCH[1]}/$seq.tgz"); done
  elif [[ "$seq" =~ ^rgbd_bonn_[a-z0-9_]+$ ]]; then
    archive="$dest/$seq.zip"
    urls=("$bonn/$seq.zip")
  else
    echo "fetch_tum: error: '$seq' is not a TUM (rgbd_dataset_freiburgN_...) or Bonn (rgbd_bonn_...) sequence name" >&2
    exit 2
  fi
  if complete "$dest/$seq"; then
    echo "fetch_tum: $seq present, skipped"
    continue
  fi
  ok=0
  for url in "${urls[@]}"; do
    echo "fetch_tum: downloading $url"
    if curl -fL --retry 3 --connect-timeout 20 -C - -o "$archive" "$url"; then ok=1; break; fi
  done
  if [ $ok -ne 1 ]; then
    echo "fetch_tum: error: could not download $seq (offline, or the site unreachable); rerun to resume" >&2
    failed+=("$seq"); continue
  fi
  if [[ "$archive" == *.zip ]]; then
    check=("$python" -m zipfile -t "$archive"); unpack=("$python" -m zipfile -e "$archive" "$dest")
  else
    check=(tar -tzf "$archive"); unpack=(tar -xzf "$archive" -C "$dest")
  fi
  if ! "${check[@]}" >/dev/null 2>&1; then
    echo "fetch_tum: error: $archive is corrupt; removed, rerun to download again" >&2
    rm -f "$archive"; failed+=("$seq"); continue
  fi
  "${unpack[@]}"
  if complete "$dest/$seq"; then
    rm -f "$archive"
    echo "fetch_tum: $seq ready in $dest/$seq"
  else
    echo "fetch_tum: error: $archive did not contain $seq/{rgb,depth,groundtruth}.txt" >&2
    failed+=("$seq")
  fi
done

if [ ${#failed[@]} -gt 0 ]; then
  echo "fetch_tum: ${#failed[@]} sequence(s) missing: ${failed[*]}" >&2
  exit 1
fi
echo "fetch_tum: all ${#sequences[@]} sequence(s) in $dest"
