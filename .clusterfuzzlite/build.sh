#!/bin/bash -eu
# Builds the cargo-fuzz targets as ClusterFuzzLite / OSS-Fuzz build them (`cargo fuzz build -O`,
# nightly, AddressSanitizer) into $OUT, with each target's seed corpus
# ($OUT/<target>_seed_corpus.zip: fuzz/seeds/ encoded into libFuzzer inputs by
# `cyclecheck fuzz --write-seeds`) and dictionary ($OUT/<target>.dict: fuzz/gcode.dict).
#
# Runs in the builder image (Dockerfile) and on any machine with a nightly toolchain and
# cargo-fuzz:   OUT=/tmp/cfl-out bash .clusterfuzzlite/build.sh
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
: "${OUT:?set OUT to the folder that receives the fuzz targets}"
mkdir -p "$OUT"
OUT="$(cd "$OUT" && pwd)"
cd "$ROOT"
TARGETS="parse_blocks diff_spec_impl impl_invariants gcode_roundtrip"

# The builder image's cargo is nightly; elsewhere take the nightly toolchain for cargo-fuzz.
if cargo --version | grep -q nightly; then FUZZ_CARGO=(cargo); else FUZZ_CARGO=(cargo +nightly); fi

# The seeds, encoded into fuzz/corpus/<target>/ by a plain build of cyclecheck (without the
# sanitizer flags the builder image puts in the environment).
(unset RUSTFLAGS CFLAGS CXXFLAGS; cargo run --quiet -p cyclecheck --bin cyclecheck -- fuzz --write-seeds)

(cd fuzz && "${FUZZ_CARGO[@]}" fuzz build -O)

for t in $TARGETS; do
    cp "fuzz/target/x86_64-unknown-linux-gnu/release/$t" "$OUT/"
    rm -f "$OUT/${t}_seed_corpus.zip"
    (cd "fuzz/corpus/$t" && zip -q -r "$OUT/${t}_seed_corpus.zip" .)
    cp fuzz/gcode.dict "$OUT/$t.dict"
done
echo "build.sh: $(echo $TARGETS | wc -w) fuzz targets, their seed corpora and dictionaries in $OUT"
