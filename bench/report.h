// The benchmark's outputs: readable tables on stdout, and every figure as JSON or CSV.
#pragma once

#include "results.h"

#include "io/output_set.h"

#include <cstdio>
#include <string>

namespace revolve::bench {

void printTables(std::FILE* out, const RunResults& results);

// Written into the outputs' temporaries (io/output_set.h), committed together by the caller: an
// output is whole or absent.
void writeJson(io::OutputSet& outputs, const std::string& path, const RunResults& results,
               const std::string& commandLine);
void writeCsv(io::OutputSet& outputs, const std::string& path, const RunResults& results);

}  // namespace revolve::bench
