#!/usr/bin/env bash
# Downloads and unpacks the TUM RGB-D sequences of the paper's Table 1.
#   bash tools/fetch_tum.sh [--dest DIR] [SEQUENCE...]
# SEQUENCE names are the TUM folder names (default: the 9 of Table 1). Resumable: partial
# archives are continued; sequences already unpacked (rgb.txt, depth.txt and groundtruth.txt
# present) are skipped; every archive is checked with `tar -tzf` before unpacking.
set -euo pipefail

dest="data/tum"
sequences=()
while [ $# -gt 0 ]; do
  case "$1" in
    --dest) dest="$2"; shift 2 ;;
    -h|--help) sed -n '2,7p' "$0"; exit 0 ;;
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
# Mirrors of the TUM RGB-D benchmark, tried in order.
mirrors=("https://cvg.cit.tum.de/rgbd/dataset" "https://vision.in.tum.de/rgbd/dataset")

command -v curl >/dev/null || { echo "fetch_tum: error: curl is required (apt-get install curl)" >&2; exit 1; }
mkdir -p "$dest"

complete() { [ -f "$1/rgb.txt" ] && [ -f "$1/depth.txt" ] && [ -f "$1/groundtruth.txt" ]; }

failed=()
for seq in "${sequences[@]}"; do
  if [[ ! "$seq" =~ ^rgbd_dataset_freiburg([123])_[a-z0-9_]+$ ]]; then
    echo "fetch_tum: error: '$seq' is not a TUM sequence name (rgbd_dataset_freiburgN_...)" >&2
    exit 2
  fi
  if complete "$dest/$seq"; then
    echo "fetch_tum: $seq present, skipped"
    continue
  fi
  archive="$dest/$seq.tgz"
  ok=0
  for mirror in "${mirrors[@]}"; do
    url="$mirror/freiburg${BASH_REMATCH[1]}/$seq.tgz"
    echo "fetch_tum: downloading $url"
    if curl -fL --retry 3 --connect-timeout 20 -C - -o "$archive" "$url"; then ok=1; break; fi
  done
  if [ $ok -ne 1 ]; then
    echo "fetch_tum: error: could not download $seq (offline, or the TUM site unreachable); rerun to resume" >&2
    failed+=("$seq"); continue
  fi
  if ! tar -tzf "$archive" >/dev/null 2>&1; then
    echo "fetch_tum: error: $archive is corrupt; removed, rerun to download again" >&2
    rm -f "$archive"; failed+=("$seq"); continue
  fi
  tar -xzf "$archive" -C "$dest"
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
