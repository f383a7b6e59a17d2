#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (build-fuzz/) and runs each for
# SECONDS (default 60), seeded with ../shared/testdata/gltf, tests/data/gltf-tools
# (meshopt and Draco files other tools wrote), tests/data/model-tools (DDS, PGM, PPM, JPEG,
# PNG and refused formats' textures; OBJ, MTL and FBX models), scenes/ and the
# regression inputs in tests/fuzz/regressions/. A crash leaves its input in
# build-fuzz/crashes/ and fails the script: fix the bug, then copy the input
# to tests/fuzz/regressions/<target>/ so the test suite keeps checking it.
# Leaks inside libassimp itself (its FBX reader's, which Atrium cannot fix from
# outside) are suppressed by tests/lsan.supp, as in the sanitized test suite.
#   scripts/fuzz.sh [SECONDS] [TARGET...]   (targets: scene_file gltf texture model)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(scene_file gltf texture model)
./scripts/install-deps.sh
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" \
  -DATRIUM_FUZZ=ON >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target scene_file_fuzzer gltf_fuzzer texture_fuzzer model_fuzzer
testdata=../shared/testdata/gltf
mkdir -p build-fuzz/crashes
status=0
for target in "${targets[@]}"; do
  corpus=build-fuzz/corpus/$target
  seeds=build-fuzz/seeds/$target
  rm -rf "$seeds" && mkdir -p "$corpus" "$seeds"
  cp tests/fuzz/regressions/$target/* "$seeds"/ 2>/dev/null || true
  if [ "$target" = scene_file ]; then
    cp scenes/*.json tests/data/*.json "$seeds"/
  elif [ "$target" = model ]; then
    # OBJ, MTL and FBX files assimp and Blender wrote, and the hostile ones.
    find tests/data/model-tools \( -name '*.obj' -o -name '*.mtl' -o -name '*.fbx' \) -size -400k -exec cp {} "$seeds"/ \;
  elif [ "$target" = texture ]; then
    # Files ImageMagick wrote: DDS (BC1, BC3, uncompressed), PGM, PPM, JPEG in
    # four layouts, TGA and BMP (one RLE, refused), the GIF, PSD and HDR
    # refused, and small PNGs.
    cp tests/data/model-tools/*.{dds,pgm,ppm,jpg,gif,psd,hdr,tga,bmp} "$seeds"/
    find tests/data/model-tools -name '*.png' -size -64k -exec cp {} "$seeds"/ \;
  else
    # Files other tools wrote: meshopt and Draco streams for the decoders.
    find tests/data/gltf-tools -name '*.glb' -size -200k -exec cp --backup=numbered {} "$seeds"/ \;
    [ -d "$testdata" ] && find "$testdata" \( -name '*.gltf' -o -name '*.glb' \) -size -2M -exec cp --backup=numbered {} "$seeds"/ \;
  fi
  echo "fuzzing $target for ${seconds}s ($(ls "$seeds" | wc -l) seeds)"
  # The seeds are read once; new inputs go to the working corpus. Inputs that
  # allocate beyond 2 GiB count as bugs too. The model target's allocation
  # stacks are unwound in full (2.5 times fewer inputs a second): the fast
  # unwinder stops in libraries built without frame pointers, and a leak
  # libassimp makes through zlib (its FBX reader gives up between inflateInit
  # and inflateEnd) then showed no libassimp frame for lsan.supp to match.
  unwind=
  [ "$target" = model ] && unwind=:fast_unwind_on_malloc=0
  if ! ASAN_OPTIONS=detect_leaks=1$unwind UBSAN_OPTIONS=print_stacktrace=1 LSAN_OPTIONS=suppressions=tests/lsan.supp:print_suppressions=0 \
      build-fuzz/fuzz/${target}_fuzzer "$corpus" "$seeds" -max_total_time="$seconds" -rss_limit_mb=3072 \
      -malloc_limit_mb=2048 -timeout=30 -print_final_stats=1 -artifact_prefix=build-fuzz/crashes/${target}- \
      > build-fuzz/${target}.log 2>&1; then
    echo "FAIL: $target crashed; input and log:" >&2
    ls build-fuzz/crashes/ >&2
    grep -E "ERROR|SUMMARY|==[0-9]+==|#[0-9]+ " build-fuzz/${target}.log | head -40 >&2
    status=1
  else
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" build-fuzz/${target}.log || true
  fi
done
exit $status
