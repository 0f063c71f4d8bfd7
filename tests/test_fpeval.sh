#!/bin/sh
# test_fpeval.sh -- src/geom/expansion.c's guard on the evaluation method
# (FLT_EVAL_METHOD) takes what is plain binary64 and refuses excess
# precision.  With the contract build's flags (the Makefile's CFLAGS_CT,
# GNU C at -O3), -march=native replaced: every src/geom/*.c compiles with
# -mavx512fp16 (FLT_EVAL_METHOD 16, as gcc 12 sets it on Intel CPUs with
# AVX512-FP16; compile only, so any x86-64 machine checks it), and
# expansion.c fails with the guard's message under -mfpmath=387 (x87
# evaluation, FLT_EVAL_METHOD 2), in the contract and the release flags.
# Needs gcc on x86-64 (skipped elsewhere).  Prints "ok NAME" / "FAIL
# NAME: why" lines; exits 1 on a failure.
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
ok() { echo "ok fpeval/$1"; }
bad() { echo "FAIL fpeval/$1: $2"; fail=1; }
GCC=${GCC:-gcc}
msg='expansion.c needs binary64 evaluation without excess precision'

case $(uname -m) in x86_64) ;; *) echo "ok fpeval/skipped # not x86-64"; exit 0 ;; esac
ct=$(cd "$top" && make -s --no-print-directory print-cflags-contract 2>/dev/null)
rel=$(cd "$top" && make -s --no-print-directory print-cflags-release 2>/dev/null)
[ -n "$ct" ] && [ -n "$rel" ] || { bad flags "make print-cflags-contract / -release printed nothing"; exit 1; }
ct=$(echo " $ct " | sed 's/ -march=native / /')

# eval FLAGS: the FLT_EVAL_METHOD those flags give
eval_method() {
    printf '#include <float.h>\nFLT_EVAL_METHOD\n' | (cd "$top" && $GCC $1 -E -) 2>/dev/null | tail -n 1 | tr -d ' '
}

fp16="$ct -mavx512fp16"
e=$(eval_method "$fp16")
[ "$e" = 16 ] && ok fp16-eval-method-16 || bad fp16-eval-method-16 "FLT_EVAL_METHOD is '$e' under $fp16"
n=0 total=0
for f in "$top"/src/geom/*.c; do
    g=src/geom/$(basename "$f") total=$((total + 1))
    if (cd "$top" && $GCC $fp16 -c -o /dev/null "$g") >"$tmp/out" 2>&1; then
        n=$((n + 1))
    else
        bad "fp16-compiles/$g" "$(head -c 400 "$tmp/out")"
    fi
done
[ $n -eq $total ] && [ $n -ge 5 ] && ok "fp16-compiles-$n-geom-files" ||
    bad fp16-compiles "$n of $total src/geom files compiled"

for kind in contract release; do
    if [ $kind = contract ]; then flags="$ct -mfpmath=387"; else flags="$rel -mfpmath=387"; fi
    e=$(eval_method "$flags")
    [ "$e" = 2 ] && ok "x87-$kind-eval-method-2" || bad "x87-$kind-eval-method-2" "FLT_EVAL_METHOD is '$e' under $flags"
    if (cd "$top" && $GCC $flags -c -o /dev/null src/geom/expansion.c) >"$tmp/out" 2>&1; then
        bad "x87-$kind-refused" "expansion.c compiled under $flags"
    elif grep -qF "$msg" "$tmp/out"; then
        ok "x87-$kind-refused"
    else
        bad "x87-$kind-refused" "failed without the guard's message: $(head -c 400 "$tmp/out")"
    fi
done
exit $fail
