#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test with ctest. GL tests run
# headless through EGL; the window test runs under xvfb-run; the WebAssembly
# page (scripts/build-web.sh) runs in headless Chromium.
#   ./test.sh             Release build in build/
#   ./test.sh --sanitize  the same suite built with ASan and UBSan in build-sanitize/, less the
#                         browser tests (label browser): WebAssembly, which the sanitizers do not see;
#                         less the run on Mesa's zink (label zink): the same test program runs
#                         sanitized on llvmpipe, and zink's bindless path adds a few lines of C++;
#                         and less the tests whose C++ the rest of the sanitized run goes through
#                         already, at a fraction of their cost under ASan (~600 s of test time):
#                         - GpuWaits and Leaks' thousand mode switches: they count GL calls that
#                           could wait and GL objects, which sanitizers do not change (the switches
#                           run sanitized in ModeSwitching's hundred, the shadow atlas's frees in
#                           AtlasAllocator and Shadows.OffGivesTheAtlasBack);
#                         - MsaaMatchesForward and TechniqueMatchesForwardShaded: cli.compare_msaa,
#                           cli.compare_phong and cli.compare_blinn_phong run every mode from every
#                           view on the same scene with MSAA and each Phong model, and
#                           Msaa.SilhouettesOfABlenderExport every G-buffer layout with MSAA;
#                         - the grid of over a quarter million clusters (57 s under ASan, 7 s without):
#                           what it adds, the scan's blocks, runs on the GPU; its C++ (the CPU's
#                           lists, the scan's dispatches) runs sanitized in the other ClusterGridTest cases;
#                         - the largest frame drawn in forward and clustered-deferred, every debug
#                           view of every mode shown and hidden, and Sponza exported to OBJ (the OBJ
#                           importer runs under ASan on the smaller OBJ/FBX tests, the regressions
#                           and the fuzzer)
set -euo pipefail
cd "$(dirname "$0")"
build=build
flags=(-DCMAKE_BUILD_TYPE=Release)
skip=()
case "${1:-}" in
  # -O1 -g1, as the sanitizers' authors advise: line tables are all a report
  # needs, and the build takes about 40% less time than at -O2 -g.
  --sanitize) build=build-sanitize
    flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
           -DATRIUM_SANITIZE=ON -DATRIUM_BUILD_BENCH=OFF)
    skip=(-LE 'browser|zink' -E '^(GpuWaits\.|Leaks\.AThousand|Modes/MsaaMatchesForward\.|Modes/TechniqueMatchesForwardShaded\.|RenderSize\.ABigSquareImage|DebugViewRender\.EveryViewAModeOffers|ModelRender\.SponzaExportedAsObj|ClusterGridTest\.AGridOfMoreThanAQuarterMillion)') ;;
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
