#include "io/clearance_file.h"

#include "io/text_files.h"

#include <cinttypes>
#include <cstdio>

namespace revolve::io {

void writeClearanceCsv(const std::string& path, const std::vector<ClearanceRow>& rows) {
  writeFileAtomically(path, [&](std::FILE* out) {
    std::fputs("pose,clearance,collides,object,px,py,pz\n", out);
    for (std::size_t pose = 0; pose < rows.size(); ++pose) {
      const ClearanceRow& row = rows[pose];
      if (row.object < 0) {
        std::fprintf(out, "%zu,inf,0,,,,\n", pose);
        continue;
      }
      std::fprintf(out, "%zu,%.9g,%d,%" PRId64 ",%.9g,%.9g,%.9g\n", pose, row.clearance, row.collides ? 1 : 0, row.object, row.px,
                   row.py, row.pz);
    }
  });
}

}  // namespace revolve::io
