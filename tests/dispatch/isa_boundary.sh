#!/bin/sh
# isa_boundary.sh NM CXXFILT BASELINE_OBJECTS ISA_OBJECTS...
#
# The per-ISA kernel objects are compiled with instruction-set flags the CPU
# may lack; everything else is compiled at the baseline ISA and runs before
# the dispatcher has checked the CPU. A symbol of vague linkage (an inline
# function, a template instantiation, an inline or static-member variable:
# nm types W, V, u) is kept once by the linker, from whichever object it meets
# first. So a per-ISA object must define no such symbol that another object of
# the library also defines: neither a baseline object (which would then run an
# AVX-512 copy on any CPU) nor an object of another ISA (SSE2 code calling an
# AVX-512 copy). The objects of one ISA are compiled with the same flags, so
# what they share is the same code. Symbols named after the xsimd
# architecture differ per ISA and never match. Fails naming every shared
# symbol, demangled.
#
# BASELINE_OBJECTS and each ISA_OBJECTS are files listing object files, one a
# line; each ISA_OBJECTS file lists the objects of one ISA and is named after
# it (avx2.txt).
set -eu

nm_tool=$1
cxxfilt=$2
baseline_list=$3
shift 3
if [ "$#" -eq 0 ]; then
    echo "no lists of per-ISA objects given" >&2
    exit 2
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The one vague symbol every object with exception tables defines: a pointer
# to the C++ personality routine, data, the same in every object.
allowed='^DW\.ref\.__gxx_personality_v0$'

demangle() {
    if [ -n "$cxxfilt" ] && command -v "$cxxfilt" >/dev/null 2>&1; then
        "$cxxfilt"
    else
        cat
    fi | awk '!seen[$0]++'  # a constructor's complete and base variants read alike
}

# Every global symbol the objects of file $1 define, one a line, sorted.
defined_in() {
    while IFS= read -r object; do
        [ -n "$object" ] || continue
        "$nm_tool" --defined-only -P "$object" | awk '$2 ~ /^[A-Zu]$/ { print $1 }'
    done <"$1" | sort -u
}

# The symbols of vague linkage object $1 defines, sorted.
vague_in() {
    "$nm_tool" --defined-only -P "$1" | awk '$2 ~ /^[WVu]$/ { print $1 }' | grep -Ev "$allowed" | sort -u || true
}

# $<TARGET_OBJECTS:obbsat> lists the per-ISA objects the library takes in too.
cat "$@" | grep -v '^$' >"$work/isa_all" || true
grep -Fxv -f "$work/isa_all" "$baseline_list" >"$work/baseline_list" || true
defined_in "$work/baseline_list" >"$work/baseline"
if [ ! -s "$work/baseline" ]; then
    echo "no symbols in the baseline objects listed in $baseline_list" >&2
    exit 2
fi

status=0
isa_count=0
for isa_list in "$@"; do
    isa=$(basename "$isa_list" .txt)
    # What the objects of every other ISA define.
    for other in "$@"; do
        [ "$other" = "$isa_list" ] || cat "$other"
    done | grep -v '^$' >"$work/others_list" || true
    defined_in "$work/others_list" >"$work/others"
    while IFS= read -r object; do
        [ -n "$object" ] || continue
        isa_count=$((isa_count + 1))
        label="$isa $(basename "$object" .o)"
        if [ -z "$("$nm_tool" --defined-only -P "$object" | head -n 1)" ]; then
            echo "$label: no symbols defined in $object" >&2
            exit 2
        fi
        vague_in "$object" >"$work/isa"
        comm -12 "$work/isa" "$work/baseline" >"$work/with_baseline"
        comm -12 "$work/isa" "$work/others" >"$work/with_others"
        if [ -s "$work/with_baseline" ] || [ -s "$work/with_others" ]; then
            status=1
            echo "$label ($object) defines, with vague linkage, symbols other objects define too:"
            if [ -s "$work/with_baseline" ]; then
                echo "  also defined by baseline objects:"
                demangle <"$work/with_baseline" | sed 's/^/    /'
            fi
            if [ -s "$work/with_others" ]; then
                echo "  also defined by the objects of another ISA:"
                demangle <"$work/with_others" | sed 's/^/    /'
            fi
        else
            echo "$label: $(wc -l <"$work/isa") symbols of vague linkage, none defined elsewhere"
        fi
    done <"$isa_list"
done

if [ "$isa_count" -eq 0 ]; then
    echo "no per-ISA objects listed in $*" >&2
    exit 2
fi
if [ "$status" -ne 0 ]; then
    echo "The per-ISA objects must keep what they compile to themselves (kernel/lanes/README.md)."
fi
exit "$status"
