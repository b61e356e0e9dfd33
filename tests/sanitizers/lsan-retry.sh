#!/bin/sh
# lsan-retry.sh ARGS...: how the sanitizer build's tests run eclat (ECLAT_BIN),
# through lsan-run.sh (which says why). Tests that signal eclat run ECLAT_BIN
# itself (tests/interrupt.test).
: "${ECLAT_BIN:?lsan-retry.sh runs ECLAT_BIN}"
exec "$(dirname "$0")/lsan-run.sh" "$ECLAT_BIN" "$@"
