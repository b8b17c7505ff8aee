#include "io/clearance_file.h"

#include "io/text_files.h"

#include <cinttypes>
#include <cstdio>

namespace revolve::io {

void writeClearanceCsv(OutputStream& out, const std::vector<ClearanceRow>& rows) {
  out.write("pose,clearance,collides,object,px,py,pz\n");
  for (std::size_t pose = 0; pose < rows.size(); ++pose) {
    const ClearanceRow& row = rows[pose];
    if (row.object < 0) {
      out.print("%zu,inf,0,,,,\n", pose);
      continue;
    }
    out.print("%zu,%.9g,%d,%" PRId64 ",%.9g,%.9g,%.9g\n", pose, row.clearance, row.collides ? 1 : 0, row.object, row.px,
              row.py, row.pz);
  }
}

}  // namespace revolve::io
