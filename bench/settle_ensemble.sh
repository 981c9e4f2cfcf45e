#!/bin/bash
# How still water stays after a pre-roll, over six tanks 0.20–0.30 m long (closed, 0.3 m deep,
# 2 cm): the largest max speed over the 2 s after `tide_rest_layers --settle S`, one line per
# tank. The figure is chaotic (docs/robustness.md § Still water): compare ensembles, not runs.
#
#   bench/settle_ensemble.sh SECONDS [more tide_rest_layers options, e.g. --quiet-speed 0.01]
set -euo pipefail
settle=${1:?usage: $0 SECONDS [tide_rest_layers options]}
shift
bin=$(dirname "$0")/../build/bin/tide_rest_layers
one() {
    local out
    out=$("$bin" --closed --length "$1" --seconds 2 --every 0.25 --settle "$settle" "${@:2}")
    echo "length $1 m: $(echo "$out" | grep '^settled' | cut -d: -f1); max speed after $(echo "$out" | awk '/^t /{print $5}' | sort -g | tail -1) m/s"
}
# Two at a time: this machine has two cores.
for pair in "0.20 0.22" "0.24 0.26" "0.28 0.30"; do
    for length in $pair; do one "$length" "$@" & done
    wait
done
