# Sourced by the comparison scripts: builds this project's library and the benchmark
# roads, then one benchmark program per library into "$out/PREFIX_opencrg" and, when
# another library is given, "$out/PREFIX_other"; sets `libs` to the names built.
#
# usage: build_programs SOURCE PREFIX [OTHER_LIB OTHER_INCLUDE_DIR]   (with $out, $roads set)
build_programs() {
    local source=$1 prefix=$2
    cargo build --release -q -p opencrg-capi
    cargo run --release -q -p opencrg-core --example make_bench_roads -- "$roads" >/dev/null
    cc -O2 -Iinclude "$source" target/release/libopencrg.a -lm -lpthread -ldl -o "$out/${prefix}_opencrg"
    libs=(opencrg)
    if [ $# -ge 4 ]; then
        cc -O2 -I"$4" "$source" "$3" -lm -lpthread -o "$out/${prefix}_other"
        libs+=(other)
    fi
}
