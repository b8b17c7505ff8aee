// The benchmark's outputs: readable tables on stdout, and every figure as JSON or CSV.
#pragma once

#include "results.h"

#include <cstdio>
#include <string>

namespace revolve::bench {

void printTables(std::FILE* out, const RunResults& results);

// Written through a temporary file renamed into place: an output is whole or absent.
void writeJson(const std::string& path, const RunResults& results, const std::string& commandLine);
void writeCsv(const std::string& path, const RunResults& results);

}  // namespace revolve::bench
