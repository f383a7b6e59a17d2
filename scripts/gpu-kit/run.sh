#!/usr/bin/env bash
# Atrium's GPU kit (made by scripts/gpu-kit.sh): every GPU figure in one
# command, started with nothing but this folder.
#   ./run.sh OUT           1920x1080, 128 to 131,072 lights, built-in scene and Sponza, each mode in
#                          the fragment and the compute stage, then the light lists' choices, and
#                          1,048,576 lights last, still and then moving (the riskiest steps) (at most 9 minutes: each step gets
#                          what is left of that); with a kit packed with --before, the version before a change
#                          against this one, run after run
#   ./run.sh OUT --quick   160x90 and few lights: checks the kit on a software renderer
# Writes into OUT: report.md (the GL context, the SMs each shader stage reaches, PSNR of every mode against forward,
# the bench tables, occlusion culling on the CPU and on the GPU), bench-atrium.csv, bench-sponza.csv, bench-shadows.csv,
# plot.png (where python3 has matplotlib), atrium.png, sponza.png and log.txt.
# Exit 0 when every step ran and every mode is within 40 dB of forward.
set -uo pipefail
kit=$(cd "$(dirname "$0")" && pwd)
usage() {
  echo "usage: run.sh OUT [--quick]" >&2
  exit 2
}
[ $# -ge 1 ] || usage
quick=0
case ${2:-} in
  --quick) quick=1 ;;
  "") ;;
  *) usage ;;
esac
mkdir -p "$1" || exit 1
out=$(cd "$1" && pwd)

export LD_LIBRARY_PATH="$kit/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# A machine with the driver but not glvnd (the lent GPU machines) takes the kit's loaders.
# (Here and below grep reads to the end, without -q: a reader that leaves early
# can end the writer by SIGPIPE, which pipefail turns into "no match".)
if ! { ldconfig -p || /sbin/ldconfig -p; } 2>/dev/null | grep 'libEGL\.so\.1 ' >/dev/null; then
  echo "run.sh: no libEGL.so.1 on this machine: using the kit's glvnd loaders" >&2
  LD_LIBRARY_PATH="$kit/glvnd:$LD_LIBRARY_PATH"
fi
export ATRIUM_SHADER_DIR="$kit/shaders" ATRIUM_TOOLS_DIR="$kit"
# glvnd finds NVIDIA's EGL through this file; some driver-only machines keep it
# where the loader does not look.
if [ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ] && [ "$quick" = 0 ]; then
  for vendor in /usr/share/glvnd/egl_vendor.d/10_nvidia.json /etc/glvnd/egl_vendor.d/10_nvidia.json; do
    if [ -f "$vendor" ]; then export __EGL_VENDOR_LIBRARY_FILENAMES=$vendor; break; fi
  done
fi

# ATRIUM_KIT_LIGHTS (a --lights list) and ATRIUM_KIT_SECONDS (the time for
# every step together) override the choices below, for a shorter window.
atrium=$kit/bin/atrium
sponza=$kit/scenes/sponza.json
if [ "$quick" = 1 ]; then
  size=160x90 lights=16 frames=1 warmup=1 shadow_lights=64 shadowed=8 picture_lights=64 picture_radius=8 cluster_lights=16 \
    assign_lights=16 million=256 budget=900 slack=4 ab_lights=16 ab_density_lights=16
else
  size=1920x1080 lights=128,1024,16384,131072 frames=5 warmup=2 shadow_lights=1024 shadowed=256 picture_lights=131072 \
    picture_radius=0.8 cluster_lights=1024,131072 assign_lights=1024,16384,131072 million=1048576 budget=540 slack=1 \
    ab_lights=1024 ab_density_lights=1024,16384
fi
lights=${ATRIUM_KIT_LIGHTS:-$lights}
budget=${ATRIUM_KIT_SECONDS:-$budget}
log=$out/log.txt
report=$out/report.md
: >"$log"
deadline=$(($(date +%s) + budget))
failed=()

# step NAME LIMIT_SECONDS OUTPUT COMMAND...: runs COMMAND with its stdout in
# OUTPUT and its stderr in the log, for at most LIMIT seconds or what is left.
# The limits are sized to a GPU lease; --quick runs on a software renderer that
# shares two cores with other tests (CI runs them two at a time, and one such
# run took the kit past its 240 s), where they only guard against a hang, so
# it gives each step four times as long.
step() {
  local name=$1 limit=$(($2 * slack)) output=$3
  shift 3
  local left=$((deadline - $(date +%s)))
  [ "$left" -lt "$limit" ] && limit=$left
  if [ "$limit" -le 0 ]; then
    echo "== $name: not run, the time is spent" | tee -a "$log" >&2
    failed+=("$name (no time left)")
    return 1
  fi
  if [ -n "$gpu_lost" ]; then
    echo "== $name: not run, $gpu_lost" | tee -a "$log" >&2
    failed+=("$name (not run: the GPU stopped answering)")
    return 1
  fi
  echo "== $name (at most ${limit} s): $*" | tee -a "$log" >&2
  local start rc
  start=$(date +%s)
  timeout "$limit" "$@" >"$output" 2>>"$log"
  rc=$?
  echo "== $name: exit $rc after $(($(date +%s) - start)) s" | tee -a "$log" >&2
  if [ "$rc" -ne 0 ]; then
    failed+=("$name (exit $rc$([ "$rc" = 124 ] && echo ', out of time'))")
    check_gpu "$name"
  fi
  return "$rc"
}

# After a step that failed: a 64x64 frame in its own process must come back
# within 20 s. A GPU that does not (a hung or reset context: after one such
# step every later frame once took 20 s and came back black) is taken for
# lost, and the steps after it are not run rather than measure a broken GPU.
gpu_lost=""
check_gpu() {
  local start rc
  start=$(date +%s)
  timeout 20 "$atrium" render --mode forward --lights 16 --size 64x64 --out "$out/.health.png" >/dev/null 2>>"$log"
  rc=$?
  echo "== GPU check after $1: exit $rc after $(($(date +%s) - start)) s" >>"$log"
  if [ "$rc" -ne 0 ]; then
    gpu_lost="the GPU did not draw a 64x64 frame within 20 s after the step '$1' (exit $rc): later figures would measure a broken GPU"
    echo "run.sh: $gpu_lost" >&2
  fi
}

# The GPU's clocks, power and temperature into the log (where nvidia-smi is):
# slow figures read differently on a throttled GPU.
gpu_state() {
  command -v nvidia-smi >/dev/null || return 0
  echo "== GPU state, $1: $(nvidia-smi --query-gpu=clocks.sm,clocks.max.sm,clocks.mem,power.draw,temperature.gpu,utilization.gpu \
    --format=csv,noheader 2>&1 | head -n 1) (SM clock, max SM clock, memory clock, power, temperature, utilisation)" >>"$log"
}

info=$out/.info.txt
if ! step "GL context" 60 "$info" "$atrium" info --lights 0; then
  echo "run.sh: atrium could not start (log: $log)" >&2
  tail -n 5 "$log" >&2
  exit 1
fi
gl=$(sed -n 's/^gl  *//p' "$info")
echo "GL context: $gl" >&2
if [ "$quick" = 0 ] && echo "$gl" | grep -qiE 'llvmpipe|softpipe|swiftshader|software'; then
  echo "run.sh: EGL gave a software renderer ($gl), not a GPU: unpack the GL loader packages and point" \
    "__EGL_VENDOR_LIBRARY_FILENAMES at the driver's EGL vendor file (docs/benchmarks.md)" >&2
  exit 1
fi

# Where shaders run, first: which of the GPU's SMs a compute dispatch and a
# full-screen fragment pass reach (NVIDIA's GL_NV_shader_thread_group), the
# same arithmetic timed in each stage, and small triangles rasterised by the
# raster pipeline and by compute (what a compute geometry pass would gain).
step "where shaders run" 60 "$out/.probe.txt" "$atrium" probe --size "$size"

# Constant density: radii shrink as lights grow (4 m at 1,024 lights, 0.4 m at
# 2^20), so each pixel is reached by about as many lights at every count.
# Each mode in both stages (--lighting-stage): the fragment passes against the
# compute passes that replace them, run for run.
bench=("$atrium" bench --modes all --views 1 --size "$size" --frames "$frames" --warmup "$warmup" --frame-limit 1000 --constant-density
  --lighting-stage fragment,compute)
gpu_state "before the runs"
step "compare, built-in scene" 90 "$out/.compare-atrium.txt" "$atrium" compare --size "$size"
step "compare, Sponza" 90 "$out/.compare-sponza.txt" "$atrium" compare "$sponza" --size "$size"
# The visibility buffer's figures first once the pictures agree: the newest
# technique (its picture failed on masked surfaces on its first GPU run), and
# the steps after these repeat figures measured before.
# It is measured against the G-buffer it replaces and forward, each
# scene at 1,024 lights (issue 42's goals): its geometry pass ("visibility")
# and its resolve ("resolve", and "material classification" when bound) are
# columns of the pass table, and --pass-steps times their parts (GL_TIMESTAMP
# queries: no wait) in brackets: the geometry pass's draws and occlusion
# culling's pyramids, the light assignment's marking, count, scan and write. Auto binds materials bindless where the driver
# has ARB_bindless_texture; the bound path (one dispatch per material) beside it.
# Their CSVs in the report give each pass's CPU time beside each system's: on
# 2026-12-04 the grid's renderer spent 5.37 ms of CPU a frame, more than its passes' GPU time.
grid_scene=$kit/scenes/courtyard-grid.json
for scene in built-in sponza grid; do
  case $scene in built-in) file=() ;; sponza) file=("$sponza") ;; grid) file=("$grid_scene") ;; esac
  step "visibility buffer, $scene" 25 "$out/.visibility-$scene.md" "$atrium" bench "${file[@]}" \
    --modes forward,clustered-deferred,visibility-buffer --views 1 --lights 1024 --size "$size" --frames "$frames" --warmup "$warmup" \
    --frame-limit 1000 --lighting-stage compute --pass-steps --csv "$out/.visibility-$scene.csv"
  step "visibility buffer bound, $scene" 20 "$out/.visibility-bound-$scene.md" "$atrium" bench "${file[@]}" \
    --modes visibility-buffer --views 1 --lights 1024 --size "$size" --frames "$frames" --warmup "$warmup" \
    --frame-limit 1000 --lighting-stage compute --material-binding bound --pass-steps
done
# The visibility buffer as a process's first mode, each binding, beside
# clustered-deferred: the bench and compare run it after raster modes, and one
# GL implementation (zink) shaded only part of the tiles of a first-mode bound
# resolve. Equal light evaluations per pixel (the heatmap's count) say every
# pixel was shaded.
firsts=(clustered-deferred:auto visibility-buffer:bound)
"$atrium" info 2>/dev/null | grep "materials bindless" >/dev/null && firsts+=(visibility-buffer:bindless)
for first in "${firsts[@]}"; do
  mode=${first%%:*} binding=${first#*:}
  step "first mode $first" 20 "$out/.first-$mode-$binding.txt" "$atrium" render --mode "$mode" --material-binding "$binding" \
    --lights 1024 --size "$size" --debug-view heatmap --out "$out/.heatmap.png"
done
# Before and after (a kit packed with --before): the version before a change
# made without a GPU (before/: its binary and shaders) against this one, on the
# same GPU, in four cases: Sponza's lion view with dense lights, the built-in
# scene at constant density and with 4x MSAA, and Blender's glass panes
# (blended surfaces, which the other scenes lack). Each case runs before,
# after, after, before, so that a GPU warming up or throttling weighs on both
# sides alike.
ab_cases=(lion density msaa glass)
ab_order=("before 1" "after 1" "after 2" "before 2")
ab_case() {  # ab_case CASE: the bench arguments of a before-and-after case
  case $1 in
    lion) echo "$sponza --modes clustered-deferred,visibility-buffer --views 4 --lights $ab_lights --light-radius 4" ;;
    density) echo "--modes clustered-deferred,visibility-buffer --views 1 --constant-density --lights $ab_density_lights" ;;
    msaa) echo "--modes clustered-deferred,visibility-buffer --views 1 --msaa 4 --lights $ab_lights" ;;
    glass) echo "$kit/assets/glass.glb --modes clustered-forward,clustered-deferred --views 1 --lights $ab_lights" ;;
  esac
}
before_atrium=$kit/before/bin/atrium
if [ -x "$before_atrium" ]; then
  for i in "${!ab_order[@]}"; do
    program=("$atrium")
    [ "${ab_order[i]% *}" = before ] && program=(env ATRIUM_SHADER_DIR="$kit/before/shaders" "$before_atrium")
    for ab in "${ab_cases[@]}"; do
      # shellcheck disable=SC2046 # the case's arguments split into words on purpose (no path holds a space)
      step "before and after: $ab, ${ab_order[i]}" 30 "$out/.ab-$ab-$i.md" "${program[@]}" bench $(ab_case "$ab") \
        --size "$size" --frames "$frames" --warmup "$warmup" --frame-limit 1000 --csv "$out/.ab-$ab-$i.csv"
    done
  done
fi
step "bench, built-in scene" 110 "$out/.bench-atrium.md" "${bench[@]}" --lights "$lights" --csv "$out/bench-atrium.csv"
step "bench, Sponza" 110 "$out/.bench-sponza.md" "${bench[@]}" "$sponza" --lights "$lights" --csv "$out/bench-sponza.csv"
step "bench, Sponza, $shadowed shadowed lights" 60 "$out/.bench-shadows.md" "${bench[@]}" "$sponza" --lights "$shadow_lights" \
  --shadows "$shadowed" --csv "$out/bench-shadows.csv"
# Clustered lists at 1080p against the grid's tile size: the default tiles are
# 32 pixels at every size (60x34 at 1080p); 16x9 makes them 120 pixels wide
# there (the default before), 64px and 16px halve and double them.
grids="16x9x32 64px 32px 24px 16px"
for grid in $grids; do
  step "clusters $grid" 40 "$out/.clusters-$grid.md" "$atrium" bench --modes clustered-deferred,tiled-deferred --views 1 --size "$size" \
    --frames "$frames" --warmup "$warmup" --frame-limit 1000 --constant-density --lights "$cluster_lights" --cluster-grid "$grid" \
    --lighting-stage compute --pass-steps
done
# Light assignment, each way forced (--light-assignment): at constant density,
# and with dense lights (Sponza's lion view, lights of 4 m), where the gather wins on llvmpipe.
for assignment in scatter gather; do
  step "assignment $assignment, built-in" 40 "$out/.assign-$assignment.md" "$atrium" bench --modes clustered-deferred,tiled-deferred \
    --views 1 --size "$size" --frames "$frames" --warmup "$warmup" --frame-limit 1000 --constant-density --lights "$assign_lights" \
    --light-assignment "$assignment" --lighting-stage compute
  step "assignment $assignment, Sponza lion" 30 "$out/.assign-lion-$assignment.md" "$atrium" bench "$sponza" \
    --modes clustered-deferred,tiled-deferred --views 4 --size "$size" --frames "$frames" --warmup "$warmup" --frame-limit 1000 \
    --lights 1024 --light-radius 4 --light-assignment "$assignment" --lighting-stage compute
done
# Occlusion culling where it tests: the grid's street view hides most of what
# is in view; the same triangles either way, the GPU path with nothing read back.
for device in cpu gpu; do
  step "occlusion culling on the $device, grid" 30 "$out/.culling-$device.md" "$atrium" bench "$grid_scene" --modes clustered-deferred,tiled-deferred \
    --views 2 --lights 1024 --size "$size" --frames "$frames" --warmup "$warmup" --frame-limit 1000 --culling "$device" \
    --csv "$out/.culling-$device.csv"
done
# Bloom's cost per pixel (its three passes in the pass table), off against on.
for bloom in 0 0.04; do
  step "bloom $bloom, built-in" 30 "$out/.bloom-$bloom.md" "$atrium" bench --modes clustered-deferred,deferred --views 1 --size "$size" \
    --frames "$frames" --warmup "$warmup" --frame-limit 1000 --lights 1024 --bloom "$bloom" --lighting-stage compute
done
# MSAA 4x in both lighting stages: the fragment stage's per-pixel and
# per-sample draws against the compute stage's shared-out edge samples, and
# the visibility buffer, which shades each triangle of a pixel once.
step "msaa 4x, built-in" 40 "$out/.msaa.md" "$atrium" bench --modes tiled-deferred,clustered-deferred,visibility-buffer --views 1 \
  --size "$size" --frames "$frames" --warmup "$warmup" --frame-limit 1000 --lights 1024 --msaa 4 --lighting-stage fragment,compute --pass-steps
gpu_state "after the bench"
step "picture, Sponza" 30 "$out/.render-sponza.txt" "$atrium" render "$sponza" --mode clustered-deferred --lights "$picture_lights" \
  --light-radius "$picture_radius" --size "$size" --out "$out/sponza.png"
step "picture, built-in scene" 30 "$out/.render-atrium.txt" "$atrium" render --mode tiled-deferred --lights 1024 --size "$size" \
  --out "$out/atrium.png"
# The riskiest step last: 2^20 lights (a stall here must not cost the figures above).
step "a million lights" 90 "$out/.million.md" "$atrium" bench --modes tiled-deferred,clustered-forward,clustered-deferred --views 1 \
  --size "$size" --frames "$frames" --warmup "$warmup" --frame-limit 1000 --constant-density --lights "$million" --lighting-stage compute
# The window's case at that count: Sponza's generated lights moving (on the GPU, the "light motion" pass).
step "a million moving lights, Sponza" 60 "$out/.million-moving.md" "$atrium" bench "$sponza" --modes clustered-deferred --views 1 \
  --size "$size" --frames "$frames" --warmup "$warmup" --frame-limit 1000 --constant-density --lights "$million" --moving-lights
plot_note="no plot: python3 with matplotlib is not on this machine"
for python in /usr/bin/python3 python3; do
  command -v "$python" >/dev/null && "$python" -c "import matplotlib" 2>/dev/null || continue
  plot_note=""
  [ -f "$out/bench-sponza.csv" ] && { "$python" "$kit/plot_bench.py" "$out/bench-sponza.csv" "$out/plot.png" \
    "Sponza, $size, $(echo "$gl" | cut -d'(' -f1)" >>"$log" 2>&1 || plot_note="the plot failed (log.txt)"; }
  break
done

ab_table() {  # the before-and-after runs' medians (the CSVs' 8th column, before any quoted field) as one table
  local header="| case | mode | lights | view |" rule="|---|---|---:|---:|" i
  for i in "${!ab_order[@]}"; do header+=" ${ab_order[i]} |" rule+="---:|"; done
  echo "$header change |"
  echo "$rule---:|"
  for ab in "${ab_cases[@]}"; do
    for i in "${!ab_order[@]}"; do
      [ -s "$out/.ab-$ab-$i.csv" ] && awk -F, -v ab="$ab" -v run="$i" -v side="${ab_order[i]% *}" \
        'NR > 1 { print ab "\t" $1 "\t" $2 "\t" $3 "\t" run "\t" side "\t" $8 }' "$out/.ab-$ab-$i.csv"
    done
  done | awk -F'\t' -v runs="${#ab_order[@]}" '
    { key = $1 "\t" $2 "\t" $3 "\t" $4; if (!(key in seen)) { seen[key] = 1; keys[++count] = key } median[key, $5] = $7; side[$5] = $6 }
    END {
      for (k = 1; k <= count; ++k) {
        split(keys[k], part, "\t")
        line = "| " part[1] " | " part[2] " | " part[3] " | " part[4] " |"
        before = after = nb = na = 0
        for (i = 0; i < runs; ++i) {
          value = ((keys[k], i) in median) ? median[keys[k], i] : "-"
          line = line " " value " |"
          if (value ~ /^[0-9.]+$/) { if (side[i] == "before") { before += value; ++nb } else { after += value; ++na } }
        }
        change = (nb && na && before > 0) ? sprintf("%+.1f%%", 100 * (after / na) / (before / nb) - 100) : "-"
        print line " " change " |"
      }
    }'
}

section() {  # section TITLE FILE: a file's text under a heading, as a code block unless it is markdown
  echo
  echo "## $1"
  echo
  if [ ! -s "$2" ]; then
    echo "(no output: see log.txt)"
  elif [[ $2 == *.md ]]; then
    cat "$2"
  else
    echo '```'
    cat "$2"
    echo '```'
  fi
}
{
  echo "# Atrium GPU kit run"
  echo
  echo "- $(cat "$kit/VERSION" | head -n 1)"
  echo "- run $(date -u +%Y-%m-%dT%H:%MZ) on $(uname -n), $(nproc) CPU cores"
  echo "- GL: $gl"
  echo "- size $size; light counts $lights at constant density; $frames frames after $warmup warm-up per run, view 1;" \
    "a run stops after a frame over 1 s"
  echo "- steps that failed: ${failed[*]:-none}"
  [ -n "$gpu_lost" ] && echo "- stopped early: $gpu_lost"
  grep "^== GPU state" "$log" | sed 's/^== /- /'
  if command -v dmesg >/dev/null && dmesg 2>/dev/null | grep "NVRM: Xid" >/dev/null; then
    echo "- the driver logged GPU faults (dmesg, NVRM Xid): $(dmesg 2>/dev/null | grep "NVRM: Xid" | tail -n 3 | tr '\n' ' ')"
  fi
  [ -n "$plot_note" ] && echo "- $plot_note"
  section "Where shaders run: SMs reached by compute and by fragment work; small triangles by the raster pipeline and by compute" "$out/.probe.txt"
  section "Every mode against forward, built-in scene (PSNR)" "$out/.compare-atrium.txt"
  section "Every mode against forward, Sponza (PSNR)" "$out/.compare-sponza.txt"
  for scene in built-in sponza grid; do
    section "Visibility buffer against clustered-deferred and forward, $scene, 1,024 lights, compute stage" "$out/.visibility-$scene.md"
    section "Visibility buffer, $scene, as CSV (each pass's and each system's CPU time)" "$out/.visibility-$scene.csv"
    section "Visibility buffer with materials bound (one dispatch per material), $scene, 1,024 lights" "$out/.visibility-bound-$scene.md"
  done
  echo
  echo "## The visibility buffer as a process's first mode (light evaluations per pixel: equal when every pixel is shaded)"
  echo
  for first in "${firsts[@]}"; do
    echo "- ${first%%:*}, material binding ${first#*:}: $(grep -h "light evaluations per pixel" "$out/.first-${first%%:*}-${first#*:}.txt" 2>/dev/null ||
      echo "no output: see log.txt")"
  done
  [[ " ${firsts[*]} " == *" visibility-buffer:bindless "* ]] ||
    echo "- visibility-buffer, material binding bindless: not run, the context lacks GL_ARB_bindless_texture"
  if [ -x "$before_atrium" ]; then
    echo
    echo "## Before and after: $(sed -n 's/^before: //p' "$kit/VERSION" | cut -d' ' -f1-2) against $(head -n 1 "$kit/VERSION" | cut -d, -f1)"
    echo
    echo "Median frame time (ms) of each run, in the order they ran; the change is the after runs' mean against the before runs'."
    echo
    ab_table
  fi
  section "Bench, built-in scene" "$out/.bench-atrium.md"
  section "Bench, Sponza" "$out/.bench-sponza.md"
  section "Bench, Sponza, $shadowed shadowed lights" "$out/.bench-shadows.md"
  for grid in $grids; do
    section "Clustered and tiled lists, compute stage, $cluster_lights lights, cluster grid $grid" "$out/.clusters-$grid.md"
  done
  for assignment in scatter gather; do
    section "Light assignment $assignment, compute stage, built-in scene, constant density" "$out/.assign-$assignment.md"
    section "Light assignment $assignment, compute stage, Sponza lion view, 1,024 lights of 4 m" "$out/.assign-lion-$assignment.md"
  done
  section "$million lights, compute stage, built-in scene, constant density" "$out/.million.md"
  section "$million moving lights, Sponza, constant density" "$out/.million-moving.md"
  for bloom in 0 0.04; do
    section "Bloom $bloom, compute stage, built-in scene, 1,024 lights" "$out/.bloom-$bloom.md"
  done
  section "MSAA 4x, both lighting stages, built-in scene, 1,024 lights" "$out/.msaa.md"
  section "Occlusion culling on the CPU (depth read back), grid, view 2" "$out/.culling-cpu.md"
  section "Occlusion culling on the GPU (nothing read back), grid, view 2" "$out/.culling-gpu.md"
  # Each pass's CPU time (cpu_passes) beside each system's (cpu_systems): the
  # renderer's CPU time outside its passes, which GPU culling's frames spent.
  for device in cpu gpu; do
    section "Occlusion culling on the $device, grid, view 2, as CSV (each pass's and each system's CPU time)" "$out/.culling-$device.csv"
  done
  section "Pictures" "$out/.render-sponza.txt"
  cat "$out/.render-atrium.txt" 2>/dev/null | sed 's/^/    /'
} >"$report"
rm -f "$out"/.*.txt "$out"/.*.md "$out"/.*.csv "$out"/.health.png "$out"/.heatmap.png
echo "run.sh: wrote $report; steps that failed: ${failed[*]:-none}" >&2
[ ${#failed[@]} -eq 0 ]
