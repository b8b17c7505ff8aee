#!/usr/bin/env bash
# The AVX2 copy of the per-ray code must define no inline (weak) function outside its own namespace:
# the linker could otherwise hand such a copy, with AVX2 instructions, to code that runs on any CPU.
# Only code counts ('W'): weak objects ('V', 'u': type_info records, which clang's UBSan emits for
# every function type it checks, and the statics of inline functions) hold no instructions.
# clang's __clang_call_terminate is two calls (__cxa_begin_catch, std::terminate) in any ISA.
# Usage: isa_symbols.sh OBJECT...
set -euo pipefail
leaks=$(nm -C --defined-only "$@" | awk '$2 == "W"' | grep -v 'revolve::detail::avx2::' |
        grep -v -x '[0-9a-f]* W __clang_call_terminate' || true)
if [[ -n "$leaks" ]]; then
  echo "weak functions outside revolve::detail::avx2 in the AVX2 object:"
  echo "$leaks"
  exit 1
fi
echo "no weak function outside revolve::detail::avx2"
