#!/usr/bin/env bash
# The AVX2 copy of the per-ray code must define no inline (weak) function outside its own namespace:
# the linker could otherwise hand such a copy, with AVX2 instructions, to code that runs on any CPU.
# Usage: isa_symbols.sh OBJECT...
set -euo pipefail
leaks=$(nm -C --defined-only "$@" | awk '$2 ~ /^[WVu]$/' | grep -v 'revolve::detail::avx2::' |
        grep -v 'DW.ref.__gxx_personality_v0' || true)
if [[ -n "$leaks" ]]; then
  echo "weak symbols outside revolve::detail::avx2 in the AVX2 object:"
  echo "$leaks"
  exit 1
fi
echo "no weak symbol outside revolve::detail::avx2"
