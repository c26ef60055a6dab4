#!/usr/bin/env bash
# Writes a fuzzing seed corpus into DIR: small crops (about 100 m square, XML and PBF) of the real
# extracts in $URBIS_SHARED_DATA (default ../shared/data), the osmnx test village, the shared
# regressions, and the small files committed under fuzz/seeds/ and tests/fuzz_crashers/. The
# extracts are not copied into the repository (their licence and size): this script cuts them
# at fuzz time. Needs osmium-tool.
#   scripts/fuzz_corpus.sh build-fuzz/corpus/osm_import_fuzz
set -euo pipefail
out=${1:?usage: scripts/fuzz_corpus.sh DIR}
root=$(cd "$(dirname "$0")/.." && pwd)
shared=${URBIS_SHARED_DATA:-$root/../shared/data}
osmnx=${URBIS_OSMNX_DATA:-/usr/share/doc/python-osmnx-doc/examples/tests/input_data}
max_bytes=65536   # scripts/fuzz.sh's -max_len: longer seeds would be cut
mkdir -p "$out"

# The box to crop from: the header's, else the data's (a file with a header box may hold far-off
# nodes of the relations it touches).
box_of() {
    local box
    box=$(osmium fileinfo -g header.boxes "$1" | head -1)
    [ -n "$box" ] || box=$(osmium fileinfo -e -g data.bbox "$1")
    echo "$box" | tr -d '()'
}

for file in "$shared"/*.osm "$shared"/*.osm.pbf; do
    [ -f "$file" ] || continue
    name=$(basename "$file"); name=${name%%.*}
    # A 3 x 3 grid of crops over the box, each 0.001 degrees (80-110 m) across, XML and PBF without
    # metadata, cut in one pass (osmium extract's config file).
    config=$(mktemp)
    awk -v box="$(box_of "$file")" -v name="$name" -v dir="$out" 'BEGIN {
        split(box, b, ","); printf "{\"directory\": \"%s\", \"extracts\": [", dir
        sep = ""
        for (i = 1; i <= 3; ++i) for (j = 1; j <= 3; ++j) for (f = 1; f <= 2; ++f) {
            x = b[1] + (b[3] - b[1]) * i / 4; y = b[2] + (b[4] - b[2]) * j / 4
            printf "%s{\"output\": \"%s_%d%d.%s\", \"output_format\": \"%s,add_metadata=false\", ", \
                sep, name, i, j, f == 1 ? "osm" : "osm.pbf", f == 1 ? "osm" : "pbf"
            printf "\"bbox\": [%.7f, %.7f, %.7f, %.7f]}", x, y, x + 0.001, y + 0.001
            sep = ", "
        }
        print "]}" }' >"$config"
    osmium extract --overwrite -s complete_ways -c "$config" "$file" >/dev/null
    rm -f "$config"
done
# Crops without a way teach nothing; crops over -max_len would be cut.
for seed in "$out"/*; do
    if ! grep -qa -e '<way' -e 'OSMData' "$seed" || [ "$(stat -c %s "$seed")" -gt "$max_bytes" ]; then rm -f "$seed"; fi
done
for file in "$osmnx/planet_10.068,48.135_10.071,48.137.osm" "$shared"/regressions/*.osm \
            "$root"/fuzz/seeds/* "$root"/tests/fuzz_crashers/*; do
    [ -f "$file" ] && cp "$file" "$out/"
done
echo "$(ls "$out" | wc -l) seeds in $out"
