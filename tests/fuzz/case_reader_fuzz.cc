// libFuzzer target for the case reader (issue 15, item 3): arbitrary bytes as a case file go
// through read_case, the two-pass ParameterHandler reading (pass 1 finds the mesh file and, for a
// .geo, its gmsh parameters; pass 2 parses every section and validates the values). Contract:
// InputError (a message naming the file and entry) or success, nothing else; no crash, no hang,
// no sanitizer report. Run by tests/fuzz/run_fuzz.sh case.
#include <deal.II/base/parameter_handler.h>

#include "input/case_file.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  static const std::string directory = [] {
    char pattern[] = "/tmp/compliant-case-fuzz-XXXXXX";
    return std::string(mkdtemp(pattern));
  }();
  const std::string file = directory + "/case.prm";
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char *>(data), static_cast<std::streamsize>(size));
  }
  compliant::CommandLine command_line;
  command_line.case_file = file;
  dealii::ParameterHandler prm;
  try
    {
      (void)compliant::read_case(command_line, prm);
    }
  catch (const compliant::InputError &)
    {
    }
  return 0;
}
