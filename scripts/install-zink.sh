#!/usr/bin/env bash
# Unpacks Mesa's zink (OpenGL on Vulkan) over lavapipe (Vulkan on the CPU) from
# Debian's bookworm-backports into a folder of its own, for the tests that need
# GL_ARB_bindless_texture: bookworm's Mesa 22.3 offers it in neither llvmpipe
# nor zink; backports' Mesa 25 zink does, on any CPU. The system's Mesa is left
# alone (the rest of the suite runs on its llvmpipe): the packages are
# downloaded with a private apt list and unpacked with dpkg -x, and the tests
# reach them through the environment in PREFIX/zink.env, which ctest sets for
# the zink tests (tests/CMakeLists.txt). Idempotent.
#   scripts/install-zink.sh [PREFIX]   (default ~/.cache/atrium/mesa-zink)
set -euo pipefail
prefix="${1:-${XDG_CACHE_HOME:-$HOME/.cache}/atrium/mesa-zink}"
[ -f "$prefix/zink.env" ] && exit 0

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/lists/partial" "$work/debs"
# bookworm too, for what backports does not carry (libvulkan1); -t takes backports' version of the rest.
printf 'deb http://deb.debian.org/debian %s main\n' bookworm bookworm-backports >"$work/sources.list"
apt_options=(-o "Dir::Etc::sourcelist=$work/sources.list" -o Dir::Etc::sourceparts=- -o "Dir::State::Lists=$work/lists"
             -o APT::Get::List-Cleanup=0 -o Debug::NoLocking=1 -o APT::Sandbox::User="$(id -un)" -t bookworm-backports)
echo "install-zink: fetching Mesa from bookworm-backports into $prefix" >&2
apt-get "${apt_options[@]}" update -qq
packages=(mesa-libgallium libgl1-mesa-dri libegl-mesa0 libgbm1 mesa-vulkan-drivers libdrm2 libdrm-amdgpu1 libdrm-intel1)
# The LLVM that backports' Mesa was built against, where the system lacks it.
# (awk reads to the end: a reader that leaves early can end apt-cache by SIGPIPE, and pipefail this script.)
llvm=$(apt-cache "${apt_options[@]}" show mesa-libgallium |
       awk '!found && /^Depends:/ && match($0, /libllvm[0-9]+/) { print substr($0, RSTART, RLENGTH); found = 1 }')
if [ -n "$llvm" ] && ! dpkg-query -W -f='${Status}' "$llvm" 2>/dev/null | grep -q "install ok installed"; then packages+=("$llvm"); fi
dpkg-query -W -f='${Status}' libvulkan1 2>/dev/null | grep -q "install ok installed" || packages+=(libvulkan1)
(cd "$work/debs" && apt-get "${apt_options[@]}" download "${packages[@]}" >&2 || true)
for package in "${packages[@]}"; do
  [ -n "$(ls "$work/debs/${package}"_*.deb 2>/dev/null)" ] || { echo "install-zink: could not download $package from Debian's archive" >&2; exit 1; }
done

rm -rf "$prefix.partial"
mkdir -p "$prefix.partial"
for deb in "$work"/debs/*.deb; do dpkg -x "$deb" "$prefix.partial"; done
lib="$prefix/usr/lib/x86_64-linux-gnu"
cat >"$prefix.partial/egl_vendor.json" <<EOF
{"file_format_version": "1.0.0", "ICD": {"library_path": "$lib/libEGL_mesa.so.0"}}
EOF
cat >"$prefix.partial/vulkan_icd.json" <<EOF
{"file_format_version": "1.0.0", "ICD": {"library_path": "$lib/libvulkan_lvp.so", "api_version": "1.3.0"}}
EOF
# One variable a line, NAME=VALUE, as ctest's ENVIRONMENT property takes them.
cat >"$prefix.partial/zink.env" <<EOF
LD_LIBRARY_PATH=$lib
LIBGL_DRIVERS_PATH=$lib/dri
__EGL_VENDOR_LIBRARY_FILENAMES=$prefix/egl_vendor.json
VK_ICD_FILENAMES=$prefix/vulkan_icd.json
GALLIUM_DRIVER=zink
LIBGL_ALWAYS_SOFTWARE=1
EGL_PLATFORM=surfaceless
EOF
rm -rf "$prefix"
mv "$prefix.partial" "$prefix"
