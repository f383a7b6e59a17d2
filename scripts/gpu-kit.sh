#!/usr/bin/env bash
# Packs one folder that gets every GPU figure in one command on a machine that
# has nothing but Linux (glibc 2.36 or newer) and an NVIDIA driver: the Release
# atrium, the shared libraries it needs that such a machine lacks (not libc or
# the driver), glvnd's GL loaders for a machine without them (glvnd/, used only
# there), shaders, scene files, the real Sponza, and run.sh
# (scripts/gpu-kit/run.sh; docs/benchmarks.md says how to run it).
#   scripts/gpu-kit.sh DIR                 builds Release atrium in build/ and packs it
#   scripts/gpu-kit.sh DIR --binary FILE   packs FILE instead (the kit test packs its build's)
#   scripts/gpu-kit.sh DIR --sponza DIR    Sponza's glTF folder (default: assets/sponza/glTF,
#                                          else ../shared/testdata/scenes/sponza-crytek)
#   scripts/gpu-kit.sh DIR --xz FILE       also writes the kit as FILE (tar.xz, about 30 MiB):
#                                          what a device run carries beside the repository
#                                          within its 64 MiB (unpack it with tar -xJf FILE -C /tmp)
#   scripts/gpu-kit.sh DIR --before TREE   also packs the version to compare with (before/: its
#                                          atrium and shaders), for run.sh's before-and-after step:
#                                          TREE is its source tree (git worktree add TREE COMMIT),
#                                          with atrium built in TREE/build (built here in Release if not)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
readonly max_bytes=$((60 * 1024 * 1024))

usage() {
  echo "usage: scripts/gpu-kit.sh DIR [--binary FILE] [--sponza DIR] [--xz FILE] [--before TREE]" >&2
  exit 2
}
[ $# -ge 1 ] || usage
kit=$1
shift
binary="" sponza="" tarball="" before=""
while [ $# -gt 0 ]; do
  case $1 in
    --binary) [ $# -ge 2 ] || usage; binary=$2; shift 2 ;;
    --sponza) [ $# -ge 2 ] || usage; sponza=$2; shift 2 ;;
    --xz) [ $# -ge 2 ] || usage; tarball=$2; shift 2 ;;
    --before) [ $# -ge 2 ] || usage; before=$(cd "$2" && pwd) || usage; shift 2 ;;
    *) usage ;;
  esac
done

if [ -z "$binary" ]; then
  cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$root/build" --target atrium -j"$(nproc)"
  binary=$root/build/atrium
fi
[ -x "$binary" ] || { echo "gpu-kit: $binary is not an executable" >&2; exit 1; }
if [ -n "$before" ]; then
  [ -d "$before/shaders" ] || { echo "gpu-kit: $before has no shaders/: --before takes a source tree" >&2; exit 1; }
  if [ ! -x "$before/build/atrium" ]; then
    cmake -S "$before" -B "$before/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
    cmake --build "$before/build" --target atrium -j"$(nproc)"
  fi
fi
if [ -z "$sponza" ]; then
  for candidate in "$root/assets/sponza/glTF" "$root/../shared/testdata/scenes/sponza-crytek"; do
    if [ -f "$candidate/Sponza.gltf" ]; then sponza=$candidate; break; fi
  done
fi
[ -n "$sponza" ] && [ -f "$sponza/Sponza.gltf" ] ||
  { echo "gpu-kit: no Sponza.gltf found; run scripts/fetch-scenes.sh sponza or pass --sponza DIR" >&2; exit 1; }

rm -rf "$kit"
mkdir -p "$kit/bin" "$kit/lib" "$kit/glvnd" "$kit/assets/sponza"
strip --strip-unneeded -o "$kit/bin/atrium" "$binary"
binaries=("$binary")
if [ -n "$before" ]; then
  mkdir -p "$kit/before/bin"
  strip --strip-unneeded -o "$kit/before/bin/atrium" "$before/build/atrium"
  cp -rL "$before/shaders" "$kit/before/shaders"
  # The before-and-after step's scene with blended surfaces (neither Sponza nor
  # the built-in scene has any): Blender's glass panes.
  cp "$root/tests/data/gltf-tools/blender-glass.glb" "$kit/assets/glass.glb"
  binaries+=("$before/build/atrium")
fi
# What the dynamic linker resolves, less what every Linux with a GL driver has:
# glibc's libraries and the GL loaders, which must be the machine's own.
ldd "${binaries[@]}" | awk '$2 == "=>" && $3 ~ /^\// { print $1, $3 }' | while read -r name path; do
  case $name in
    libc.so.* | libm.so.* | libdl.so.* | libpthread.so.* | librt.so.* | ld-linux* | libGL* | libEGL* | libOpenGL*) continue ;;
  esac
  cp -L "$path" "$kit/lib/$name"
done
# glvnd's loaders dispatch to whichever vendor library the machine's driver
# installed (NVIDIA's, through its EGL vendor file): the lent GPU machines have
# the driver without them. run.sh puts them on the path only where the dynamic
# linker finds no libEGL.so.1 of the machine's own.
for name in libEGL.so.1 libOpenGL.so.0 libGL.so.1 libGLX.so.0 libGLdispatch.so.0; do
  # awk reads to the end: leaving at the first match can end ldconfig by
  # SIGPIPE, which pipefail turns into a silent exit of this script.
  path=$({ ldconfig -p 2>/dev/null || /sbin/ldconfig -p; } | awk -v n="$name" '!found && $1 == n && /x86-64/ { print $NF; found = 1 }')
  [ -n "$path" ] || { echo "gpu-kit: this machine has no $name (Debian: apt-get install libegl1 libopengl0 libgl1)" >&2; exit 1; }
  cp -L "$path" "$kit/glvnd/$name"
done
cp -r "$root/shaders" "$kit/shaders"
cp -r "$root/scenes" "$kit/scenes"
cp -rL "$sponza" "$kit/assets/sponza/glTF"
cp "$root/tools/plot_bench.py" "$kit/plot_bench.py"
cp "$root/scripts/gpu-kit/run.sh" "$kit/run.sh"
chmod +x "$kit/run.sh"
{
  echo "atrium $(git -C "$root" describe --always --dirty 2>/dev/null || echo unknown), kit made $(date -u +%Y-%m-%dT%H:%MZ)"
  echo "binary: $binary"
  [ -z "$before" ] || echo "before: atrium $(git -C "$before" describe --always --dirty 2>/dev/null || echo unknown) ($before)"
} >"$kit/VERSION"

# What a device run carries is the tarball where there is one, else the folder.
bytes=$(du -sb "$kit" | cut -f1)
echo "gpu-kit: $kit ($((bytes / 1024 / 1024)) MiB, $(ls "$kit/lib" | wc -l) libraries); run: $kit/run.sh OUT [--quick]"
carried=$kit
if [ -n "$tarball" ]; then
  mkdir -p "$(dirname "$tarball")"
  tar -C "$(dirname "$kit")" -cf - "$(basename "$kit")" | xz -T0 -4 >"$tarball"
  bytes=$(stat -c %s "$tarball") carried=$tarball
  echo "gpu-kit: $tarball ($((bytes / 1024 / 1024)) MiB); on the GPU machine: tar -xJf $(basename "$tarball") -C /tmp && /tmp/$(basename "$kit")/run.sh OUT"
fi
if [ "$bytes" -gt "$max_bytes" ]; then
  echo "gpu-kit: $carried holds $((bytes / 1024 / 1024)) MiB, more than the 60 MiB a device run may carry" >&2
  exit 1
fi
