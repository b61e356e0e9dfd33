#!/bin/sh
# lsan-run.sh PROGRAM ARGS...: how the sanitizer build's tests run a program,
# eclat (through lsan-retry.sh) or one of tests/'s C programs (LSAN_RUN, and
# automake's LOG_COMPILER for the programs in TESTS).
# LeakSanitizer's own tracer can crash while it stops the threads at exit
# ("Tracer caught signal 11 ... LeakSanitizer has encountered a fatal error",
# google/sanitizers#1353): a failure of the checker that says nothing about the
# program. It happens for a few runs out of about a thousand (planes in
# povray_path.test, the glass slab in materials.test, warn_each_place in
# bad.test, test_csg once). Such a run is made once more with the leak check
# off, AddressSanitizer and UndefinedBehaviorSanitizer still on; any other
# outcome, a real leak report included, is passed on as it is, standard error
# and exit status alike. Standard output is not held back: a program rerun
# prints its output twice, and its second exit status is the one that counts.
[ $# -ge 1 ] || { echo "usage: lsan-run.sh PROGRAM ARGS..." >&2; exit 2; }
err=$(mktemp "${TMPDIR:-/tmp}/lsan-run.XXXXXX") || exit 1
"$@" 2> "$err"
status=$?
if grep -q 'LeakSanitizer has encountered a fatal error' "$err"; then
	ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0" "$@" 2> "$err"
	status=$?
fi
cat "$err" >&2
rm -f "$err"
exit "$status"
