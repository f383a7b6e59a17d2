#!/usr/bin/env bash
# Downloads the real scenes into the git-ignored assets/ folder and checks them.
#   scripts/fetch-scenes.sh sponza   Crytek Sponza, glTF, from Khronos' glTF-Sample-Assets
#   scripts/fetch-scenes.sh bistro   Amazon Lumberyard Bistro v5.2 from NVIDIA ORCA, as shipped:
#                                    FBX with DDS textures, opened directly (no conversion)
# Needs network access; installs git, curl and unzip when missing.
set -euo pipefail
cd "$(dirname "$0")/.."
assets=assets

need() {
  local missing=()
  for tool in "$@"; do command -v "${tool%%:*}" >/dev/null || missing+=("${tool#*:}"); done
  if [ ${#missing[@]} -gt 0 ]; then
    local sudo_cmd=(); [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
    "${sudo_cmd[@]}" apt-get update -qq && "${sudo_cmd[@]}" apt-get install -y -qq "${missing[@]}"
  fi
}

check() {  # check FILE MIN_BYTES: the file exists and is not a truncated download
  local file=$1 min=$2
  if [ ! -f "$file" ] || [ "$(stat -c %s "$file")" -lt "$min" ]; then
    echo "fetch-scenes: $file is missing or smaller than $min bytes; the download failed" >&2
    exit 1
  fi
}

fetch_sponza() {
  need git:git
  local target=$assets/sponza repo=https://github.com/KhronosGroup/glTF-Sample-Assets.git
  local work; work=$(mktemp -d)
  git clone --quiet --depth 1 --filter=blob:none --sparse "$repo" "$work/repo"
  git -C "$work/repo" sparse-checkout set Models/Sponza/glTF
  rm -rf "$target" && mkdir -p "$target"
  cp -r "$work/repo/Models/Sponza/glTF" "$target/glTF"
  rm -rf "$work"
  check "$target/glTF/Sponza.gltf" 100000
  check "$target/glTF/Sponza.bin" 5000000
  local images; images=$(find "$target/glTF" -name '*.png' -o -name '*.jpg' | wc -l)
  [ "$images" -ge 60 ] || { echo "fetch-scenes: expected about 69 Sponza textures, found $images" >&2; exit 1; }
  echo "Sponza is in $target; run: ./run.sh scenes/sponza.json"
}

# Bistro_v5_2.zip as NVIDIA's ORCA page serves it (no login), else the
# casual-effects mirror; BISTRO_URL tries another address first. Whatever
# answers must be exactly the archive: its size and SHA-256 are checked.
bistro_size=894377473
bistro_sha256=0d50e3c724c6c5da19f8eb99ad3f53e36fec37ffa2df9621f9ccf0603f3934e1

is_bistro_zip() {
  [ -f "$1" ] && [ "$(stat -c %s "$1")" -eq "$bistro_size" ] && [ "$(sha256sum "$1" | cut -d' ' -f1)" = "$bistro_sha256" ]
}

fetch_bistro() {
  need curl:curl unzip:unzip
  local target=$assets/bistro zip=$assets/bistro/Bistro_v5_2.zip
  local urls=(${BISTRO_URL:+"$BISTRO_URL"} https://developer.nvidia.com/bistro https://developer.nvidia.com/downloads/bistro
              https://casual-effects.com/g3d/data10/research/model/Amazon_Lumberyard_Bistro/Bistro_v5_2.zip)
  mkdir -p "$target"
  if ! is_bistro_zip "$zip"; then
    for url in "${urls[@]}"; do
      echo "fetch-scenes: downloading Bistro_v5_2.zip (894 MB) from $url"
      if curl -fL --retry 3 -o "$zip.part" "$url" && mv "$zip.part" "$zip" && is_bistro_zip "$zip"; then break; fi
      [ -f "$zip" ] && echo "fetch-scenes: what $url served is $(stat -c %s "$zip") bytes, not Bistro_v5_2.zip ($bistro_size bytes, SHA-256 ${bistro_sha256:0:12}...)" >&2
      rm -f "$zip" "$zip.part"
    done
  fi
  is_bistro_zip "$zip" || { echo "fetch-scenes: no address served Bistro_v5_2.zip; download it from https://developer.nvidia.com/bistro into $target and run this again" >&2; exit 1; }
  unzip -q -o "$zip" -d "$target"
  check "$target/Bistro_v5_2/BistroExterior.fbx" 50000000
  local textures; textures=$(find "$target/Bistro_v5_2" -iname '*.dds' | wc -l)
  [ "$textures" -ge 100 ] || { echo "fetch-scenes: expected Bistro's DDS textures in $target/Bistro_v5_2/Textures, found $textures" >&2; exit 1; }
  echo "Bistro is in $target/Bistro_v5_2 (the archive stays beside it); run: ./run.sh scenes/bistro.json"
}

case "${1:-}" in
  sponza) fetch_sponza ;;
  bistro) fetch_bistro ;;
  *) echo "usage: scripts/fetch-scenes.sh sponza|bistro" >&2; exit 2 ;;
esac
