#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test with ctest. GL tests run
# headless through EGL; the window test runs under xvfb-run; the WebAssembly
# page (scripts/build-web.sh) runs in headless Chromium.
#   ./test.sh             Release build in build/
#   ./test.sh --sanitize  the same suite built with ASan and UBSan in build-sanitize/, less the
#                         browser tests (label browser): WebAssembly, which the sanitizers do not see;
#                         less the run on Mesa's zink (label zink): the same test program runs
#                         sanitized on llvmpipe, and zink's bindless path adds a few lines of C++;
#                         and less the tests in sanitize_skips below, whose C++ the rest of the
#                         sanitized run goes through already at a fraction of their cost under ASan.
set -euo pipefail
cd "$(dirname "$0")"
build=build
flags=(-DCMAKE_BUILD_TYPE=Release)
skip=()
case "${1:-}" in
  # -O1 -g1, as the sanitizers' authors advise: line tables are all a report
  # needs, and the build takes about 40% less time than at -O2 -g. Built by
  # clang, the fuzzers' compiler, in half the time gcc takes (316 s against
  # 626 s on the 2-core machine, with the same tests passing).
  --sanitize) build=build-sanitize
    flags=(-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
           -DATRIUM_SANITIZE=ON -DATRIUM_BUILD_BENCH=OFF)
    # What the sanitized run leaves out (about 1,000 s of test time under ASan), and
    # where the same C++ runs sanitized instead. Sanitizers find memory and undefined
    # behaviour in Atrium's C++, not wrong pixels: a matrix of modes, views or cases
    # adds pictures, and every mode's passes, every G-buffer layout and every option
    # still draw sanitized at least once.
    sanitize_skips=(
      # They count GL calls that could wait and GL objects, which sanitizers do not change:
      # the switches run sanitized in ModeSwitching's hundred, the shadow atlas's frees in
      # AtlasAllocator and Shadows.OffGivesTheAtlasBack.
      'GpuWaits\.' 'Leaks\.AThousand'
      # Every mode against forward from every view: every mode and layout draws both of
      # its stages sanitized in Modes/ComputeStage, and once more in cli.compare_all_modes.
      'Modes/TechniqueMatchesForward\.' 'Modes/TechniqueMatchesForwardShaded\.' 'cli\.compare_(phong|blinn_phong)$'
      # Every mode with MSAA: Msaa.SilhouettesOfABlenderExport draws every G-buffer layout
      # with it, ComputeFreeTier the compute-free tier's.
      'Modes/MsaaMatchesForward\.' 'Msaa\.BringsEveryModeCloser' 'cli\.compare_msaa$'
      # The edge cases of light volumes in the modes that draw none: the volume modes and
      # deferred-radius still draw every case.
      'Modes/VolumeEdgeCase\.MatchesForward/(deferred|light_prepass|tiled_deferred|clustered_forward|clustered_deferred|visibility_buffer)_(full|compact)_'
      'Modes/VolumeEdgeCase\.MatchesForward/(light_volumes|light_volumes_instanced|deferred_radius)_compact_'
      # Every mode with shadows and occlusion culling: cli.compare_shadows draws every mode
      # with shadows, the other OcclusionCulling cases and OcclusionCullingTwins cull on both devices.
      'Shadows\.EveryModeDraws' 'Device/OcclusionCulling\.EveryModeDraws'
      # Sponza in every mode, on either tier: Sponza loads and draws sanitized in the other
      # SponzaScene cases, the compute-free tier in context_tier_es3.0 and ComputeFreeTier.
      'SponzaScene\.EveryModeDraws' 'ComputeFreeTier\.EveryModeDrawsTheFullTiersPictureOfSponza'
      # OpenGL 4.1 hides less than ES 3.0, whose run takes every emulated entry point.
      'context_tier_gl4\.1$'
      # Every debug view of every mode shown and hidden: EveryResourceViewOfEveryModeDraws
      # and the other DebugViewRender cases draw them.
      'DebugViewRender\.EveryViewAModeOffers'
      # The largest frame, Sponza exported to OBJ (the OBJ importer runs on the smaller OBJ
      # and FBX tests, the regressions and the fuzzer), and the grid of over a quarter
      # million clusters (57 s under ASan): what it adds, the scan's blocks, runs on the
      # GPU; the other ClusterGridTest cases run its C++.
      'RenderSize\.ABigSquareImage' 'ModelRender\.SponzaExportedAsObj' 'ClusterGridTest\.AGridOfMoreThanAQuarterMillion'
    )
    skip=(-LE 'browser|zink' -E "^($(IFS='|'; echo "${sanitize_skips[*]}"))") ;;
  "") ;;
  *) echo "usage: ./test.sh [--sanitize]" >&2; exit 2 ;;
esac
./scripts/install-deps.sh
# Mesa's zink beside the system's Mesa, for the bindless-texture tests (label
# zink). Where the archive cannot be reached they are left out, and said so:
# the rest of the suite does not need them.
./scripts/install-zink.sh || echo "test.sh: Mesa's zink is not installed: the zink tests (bindless textures) will not run" >&2
cmake -S . -B "$build" "${flags[@]}" >/dev/null
cmake --build "$build" -j"$(nproc)"
# The page that the browser test (web.browser) opens in headless Chromium.
[ ${#skip[@]} -gt 0 ] || ./scripts/build-web.sh >/dev/null
cd "$build"
# ctest starts the longest tests first when it knows their times; a fresh
# build folder does not, and one long test started last keeps a core idle for
# minutes. tests/ctest-costs.txt holds the times of the tests over 3 s on the
# 2-core CI machine (ctest's own format); ctest updates the copy from then on.
costs=Testing/Temporary/CTestCostData.txt
[ -e "$costs" ] || { mkdir -p "$(dirname "$costs")" && cp ../tests/ctest-costs.txt "$costs"; }
ctest --output-on-failure -j"$(nproc)" "${skip[@]}"
