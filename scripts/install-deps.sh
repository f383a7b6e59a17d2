#!/usr/bin/env bash
# Installs Atrium's build and test dependencies from Debian's archive.
# Idempotent: when every package is present and this package list was already
# installed once on this machine, it returns at once without touching apt.
# The first run on a machine also upgrades Mesa, whose llvmpipe driver runs the
# headless tests: an image may carry an older Mesa than the archive serves.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libglm-dev libglfw3-dev libtinygltf-dev libstb-dev libspng-dev libturbojpeg0-dev nlohmann-json3-dev
  libepoxy-dev libegl-dev libgl-dev libimgui-dev libmeshoptimizer-dev libdraco-dev libsquish-dev libassimp-dev libtinyobjloader-dev libcli11-dev zlib1g-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth xdotool python3 python3-matplotlib python3-numpy
  clang libclang-rt-14-dev
  emscripten nodejs googletest chromium
)
mesa_packages=(libgl1-mesa-dri libegl-mesa0 libglx-mesa0 libgbm1)

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi

list_hash=$(printf '%s\n' "${packages[@]}" "${mesa_packages[@]}" | sha1sum | cut -c1-12)
stamp_dir="${XDG_CACHE_HOME:-$HOME/.cache}/atrium"
stamp="$stamp_dir/deps-$list_hash"

missing=()
for p in "${packages[@]}" "${mesa_packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [ "$status" = "install ok installed" ] || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ] && [ -f "$stamp" ]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]:-(none missing)} and upgrading Mesa" >&2
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
# Naming installed Mesa packages in `install` upgrades them to the archive's version.
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${packages[@]}" "${mesa_packages[@]}" >/dev/null
mkdir -p "$stamp_dir" && touch "$stamp"
