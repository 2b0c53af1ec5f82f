#!/usr/bin/env bash
# Downloads person detectors for `mask_source: detector` (configs/ipl.json) into data/models/
# (git-ignored) and checks each file against its published checksum.
#   bash tools/fetch_models.sh [--dest DIR] [MODEL...]
# MODEL (default: body):
#   body          Yolo-Fastest 1.1 body: one class (person), 1.2 MB, Darknet, 320x320 input; the
#                 model configs/ipl.json names and the docs' figures are measured with
#   yolov4-tiny   YOLOv4-tiny, the 80 COCO classes (0 = person), 23 MB, Darknet, 416x416 input:
#                 --set detector.model=data/models/yolov4-tiny.weights
#                 --set detector.config=data/models/yolov4-tiny.cfg --set detector.input_size=416
# Files already present with the right checksum are skipped; a download that fails (offline) or
# does not match is removed and named, and the exit code is 1.
set -euo pipefail

dest="data/models"
models=()
while [ $# -gt 0 ]; do
  case "$1" in
    --dest) dest="$2"; shift 2 ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    -*) echo "fetch_models: error: unknown option '$1' (expected --dest DIR or model names)" >&2; exit 2 ;;
    *) models+=("$1"); shift ;;
  esac
done
[ ${#models[@]} -gt 0 ] || models=(body)

# file|url|algorithm|checksum, per model. The body model is pinned to a commit of the public
# Yolo-Fastest model zoo (SHA-256 of those files); YOLOv4-tiny's weights to the SHA-1 OpenCV's
# test-data downloader publishes for that release. Its .cfg has no published checksum: it is
# taken from the darknet repository as is, and checked by loading it (dynvo-cli names the file
# when OpenCV cannot).
zoo="https://raw.githubusercontent.com/dog-qiuqiu/Yolo-Fastest/9c62b1c50e024fb73d29a651133b1d63548e63a1/ModelZoo/yolo-fastest-1.1_body"
files_of() {
  case "$1" in
    body)
      echo "yolo-fastest-1.1_body.cfg|$zoo/yolo-fastest-1.1_body.cfg|sha256|045b8e276ebe3924474da8c866b7e709159ea067137b5d66bf9dd560411b2c1a"
      echo "yolo-fastest-1.1_body.weights|$zoo/yolo-fastest-1.1_body.weights|sha256|5bbb6d878f6e2eb3deee39e91dc6f9b39700e99ec83fa94d258670a554949728"
      ;;
    yolov4-tiny)
      echo "yolov4-tiny.cfg|https://raw.githubusercontent.com/AlexeyAB/darknet/master/cfg/yolov4-tiny.cfg|none|"
      echo "yolov4-tiny.weights|https://github.com/AlexeyAB/darknet/releases/download/yolov4/yolov4-tiny.weights|sha1|451caaab22fb9831aa1a5ee9b5ba74a35ffa5dcb"
      ;;
    *) return 1 ;;
  esac
}

# checked FILE ALGORITHM CHECKSUM: true when FILE exists and matches (any file for "none").
checked() {
  [ -s "$1" ] || return 1
  [ "$2" = none ] && return 0
  [ "$("${2}sum" "$1" | cut -d' ' -f1)" = "$3" ]
}

for model in "${models[@]}"; do
  files_of "$model" >/dev/null || {
    echo "fetch_models: error: unknown model '$model' (expected body or yolov4-tiny)" >&2; exit 2; }
done
command -v curl >/dev/null || { echo "fetch_models: error: curl is required (apt-get install curl)" >&2; exit 1; }
mkdir -p "$dest"
failed=()
for model in "${models[@]}"; do
  entries="$(files_of "$model")"
  while IFS='|' read -r file url algorithm checksum; do
    path="$dest/$file"
    if checked "$path" "$algorithm" "$checksum"; then echo "fetch_models: $path present, checked"; continue; fi
    echo "fetch_models: downloading $url"
    if ! curl -fL --retry 3 --connect-timeout 20 -o "$path.part" "$url"; then
      echo "fetch_models: error: could not download $url (offline, or the site unreachable)" >&2
      rm -f "$path.part"; failed+=("$path"); continue
    fi
    if ! checked "$path.part" "$algorithm" "$checksum"; then
      echo "fetch_models: error: $url does not match its $algorithm checksum $checksum; removed" >&2
      rm -f "$path.part"; failed+=("$path"); continue
    fi
    mv "$path.part" "$path"
    echo "fetch_models: $path ready"
  done <<< "$entries"
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fetch_models: ${#failed[@]} file(s) missing: ${failed[*]}" >&2
  exit 1
fi
echo "fetch_models: ${models[*]} in $dest"
