#!/usr/bin/env bash
# Downloads the real scenes into the git-ignored assets/ folder and checks them.
#   scripts/fetch-scenes.sh sponza   Crytek Sponza, glTF, from Khronos' glTF-Sample-Assets
#   scripts/fetch-scenes.sh bistro   Amazon Lumberyard Bistro (exterior), from NVIDIA ORCA (FBX),
#                                    converted to glTF binary with assimp
# Needs network access; installs git, curl, unzip and assimp-utils when missing.
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

fetch_bistro() {
  need curl:curl unzip:unzip assimp:assimp-utils
  local target=$assets/bistro
  # NVIDIA's Open Research Content Archive serves Bistro as FBX; BISTRO_URL overrides the address.
  local url=${BISTRO_URL:-https://developer.download.nvidia.com/ORCA/BISTRO/Bistro_v5_2.zip}
  local work; work=$(mktemp -d)
  curl -fL --retry 3 -o "$work/bistro.zip" "$url"
  unzip -q "$work/bistro.zip" -d "$work/bistro"
  local fbx; fbx=$(find "$work/bistro" -iname 'BistroExterior.fbx' | head -n 1)
  [ -n "$fbx" ] || { echo "fetch-scenes: BistroExterior.fbx is not in $url" >&2; exit 1; }
  mkdir -p "$target"
  (cd "$(dirname "$fbx")" && assimp export "$(basename "$fbx")" "$OLDPWD/$target/BistroExterior.glb" -fglb2)
  rm -rf "$work"
  check "$target/BistroExterior.glb" 50000000
  echo "Bistro is in $target; run: ./run.sh scenes/bistro.json"
}

case "${1:-}" in
  sponza) fetch_sponza ;;
  bistro) fetch_bistro ;;
  *) echo "usage: scripts/fetch-scenes.sh sponza|bistro" >&2; exit 2 ;;
esac
