#!/usr/bin/env bash
# scripts/gpu-kit.sh packs this build's atrium into a kit, and the kit's
# run.sh --quick runs from that folder alone (an environment emptied of
# everything but PATH, so the libraries come from the kit): every step passes,
# every mode agrees with forward on both scenes in both lighting stages, each
# mode is benched in both, and OUT holds the files the kit promises, no more than 8.
# The kit is packed with a version to compare with (--before: here a source tree
# of this build's binary and shaders), whose runs make the before-and-after table.
#   gpu_kit_test.sh ATRIUM_BINARY WORK_DIR
set -euo pipefail
binary=$1 work=$2
root=$(cd "$(dirname "$0")/../.." && pwd)
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
rm -rf "$work"
mkdir -p "$work"
mkdir -p "$work/before/build"
ln -s "$(realpath "$binary")" "$work/before/build/atrium"
ln -s "$root/shaders" "$work/before/shaders"
"$root/scripts/gpu-kit.sh" "$work/kit" --binary "$binary" --xz "$work/kit.tar.xz" --before "$work/before"

# The tarball a device run carries holds the kit, and the kit's glvnd loaders
# (for a machine with the driver alone) dispatch to the machine's driver: here
# Mesa's, through its EGL vendor file.
tar -tJf "$work/kit.tar.xz" >"$work/tarball.txt"
grep -qx "kit/run.sh" "$work/tarball.txt" || fail "the tarball holds no kit/run.sh"
grep -qx "kit/glvnd/libEGL.so.1" "$work/tarball.txt" || fail "the tarball holds no glvnd loader"
env -i PATH=/usr/bin:/bin LD_LIBRARY_PATH="$work/kit/glvnd:$work/kit/lib" LD_DEBUG=libs ATRIUM_SHADER_DIR="$work/kit/shaders" \
  "$work/kit/bin/atrium" info >"$work/glvnd.txt" 2>&1 || fail "atrium info fails through the kit's loaders: $(tail -n 5 "$work/glvnd.txt")"
grep -q "calling init: $work/kit/glvnd/libEGL.so.1" "$work/glvnd.txt" || fail "the kit's libEGL.so.1 was not the one loaded"
grep -q "^gl  .*egl-surfaceless" "$work/glvnd.txt" || fail "no GL context through the kit's loaders: $(grep -v "^ *[0-9]*:" "$work/glvnd.txt")"

# Every library the kit's atrium loads comes from the kit, except those the
# kit leaves to the machine: glibc's and the GL loaders.
env -i PATH=/usr/bin:/bin LD_LIBRARY_PATH="$work/kit/lib" ldd "$work/kit/bin/atrium" >"$work/ldd.txt"
while read -r name arrow path _; do
  [ "$arrow" = "=>" ] || continue
  case $name in
    libc.so.* | libm.so.* | libdl.so.* | libpthread.so.* | librt.so.* | libGL* | libEGL* | libOpenGL*) continue ;;
  esac
  [[ $path == "$work/kit/lib/"* ]] || fail "$name loads from $path, not from the kit"
done <"$work/ldd.txt"
[ ! -e "$work/kit/lib/libc.so.6" ] || fail "the kit carries libc"

env -i PATH=/usr/bin:/bin HOME="$work" "$work/kit/run.sh" "$work/out" --quick 2>"$work/run.log" ||
  fail "run.sh --quick failed: $(tail -n 20 "$work/run.log")"

report=$work/out/report.md
[ "$(grep -c "every mode is within 40 dB PSNR of forward" "$report")" = 2 ] || fail "both scenes' PSNR tables: $(cat "$report")"
grep -q "steps that failed: none" "$report" || fail "a step failed: $(cat "$report")"
grep -q "^| lights | forward/fragment | deferred/fragment |" "$report" || fail "no bench table of both stages in the report"
grep -q "^compute .* ms, .* Gflop/s" "$report" || fail "no stage probe in the report"
grep -q "^  pixels a triangle  triangles   raster ms" "$report" || fail "no raster probe in the report"
[ "$(grep -c "^ *[0-9.]*  *[0-9]*  .*  0 of [0-9]*" "$report")" = 4 ] ||
  fail "the raster probe's two sides disagree, or a triangle size is missing: $(cat "$report")"
grep -q "^## 256 lights, compute stage" "$report" || fail "no million-light step (256 in --quick)"
grep -q "^## 256 moving lights, Sponza" "$report" || fail "no million-moving-light step (256 in --quick)"
grep -q "the scene's animated lights moving" "$report" || fail "the moving lights' bench did not move them: $(cat "$report")"
[ "$(grep -c "^## Clustered and tiled lists, compute stage" "$report")" = 5 ] || fail "not every cluster grid measured"
[ "$(grep -c "^## Light assignment \(scatter\|gather\), compute stage" "$report")" = 4 ] || fail "not every light assignment measured"
[ "$(grep -c "^- visibility-buffer, material binding \(bound\|bindless\): light evaluations per pixel: [0-9.]* on average" "$report")" = 1 ] ||
  fail "no first-mode check of the visibility buffer (llvmpipe: bound runs, bindless is refused): $(cat "$report")"
[ "$(grep -c "^## Visibility buffer with materials bound" "$report")" = 3 ] || fail "the visibility buffer's bound path not measured in every scene"
grep -q "^| lights | tiled-deferred/fragment | clustered-deferred/fragment | visibility-buffer/fragment | tiled-deferred/compute | clustered-deferred/compute | visibility-buffer/compute |" "$report" ||
  fail "no MSAA table of both stages in the report"
grep -q "^| clustered-deferred | 16 | 1 .*| 16x9x32 clusters, gather at density [0-9.]* | [^|]* |$" "$report" || fail "no gathered clustered row at 160x90: $(cat "$report")"
for scene in atrium sponza shadows; do
  csv=$work/out/bench-$scene.csv
  [ -s "$csv" ] || fail "$csv is missing"
  head -n 1 "$csv" | grep -q ",gpu_ms,gpu_waits,skipped,lighting_stage,light_lists,cpu_systems,pipelined_ms,technique_variant,pass_steps,paced_ms$" || fail "$csv has no lighting_stage, light_lists, cpu_systems, pipelined_ms, technique_variant, pass_steps and paced_ms columns"
  grep -q ",compute,\"" "$csv" || fail "$csv has no run in the compute stage"
  # Every mode in the technique table has a row.
  for mode in forward deferred deferred-radius light-volumes tiled-deferred clustered-forward clustered-deferred \
    light-volumes-instanced light-prepass; do
    grep -q "^$mode," "$csv" || fail "$csv has no row for $mode"
  done
done
# The grid's culling runs as CSV too: the renderer's CPU time against its passes'.
[ "$(grep -c "^clustered-deferred,1024,2,court,.*Render/mesh_renderer=" "$report")" = 2 ] ||
  fail "no CSV rows of the grid's culling runs (cpu_passes, cpu_systems) in the report"
[ "$(grep -c "^visibility-buffer,1024,1,.*Render/mesh_renderer=" "$report")" = 3 ] ||
  fail "no CSV rows of the visibility buffer's runs in every scene (cpu_passes, cpu_systems) in the report"
# Before and after: each case's modes, each with a median from all four runs and a change.
grep -q "^## Before and after: atrium .* against atrium " "$report" || fail "no before-and-after section: $(cat "$report")"
grep -q "^| case | mode | lights | view | before 1 | after 1 | after 2 | before 2 | change |$" "$report" ||
  fail "no before-and-after table"
[ "$(grep -cE "^\| (lion|density|msaa|glass) \| [a-z-]+ \| 16 \| [14] \|( [0-9.]+ \|){4} [+-][0-9.]+% \|$" "$report")" = 8 ] ||
  fail "not every case measured in all four runs: $(grep -A 9 "^## Before and after" "$report")"
for png in sponza.png atrium.png; do
  [ "$(head -c 4 "$work/out/$png" | tail -c 3)" = PNG ] || fail "$png is not a PNG"
done
files=$(find "$work/out" -type f | wc -l)
[ "$files" -le 8 ] || fail "OUT holds $files files, more than 8: $(ls -a "$work/out")"
echo "gpu kit: $(du -sh "$work/kit" | cut -f1), --quick wrote $files files"
rm -rf "$work"
