// Rewrites the measured table of docs/properties.md (between its markers) with a fresh audit of
// every family of tests/tools/property_families.hpp; the rest of the document is kept.
//   write_properties [document]   (default: docs/properties.md of the source tree)
// test_analysis fails, naming this command, when the document's table differs from the measurement.
#include "tools/property_families.hpp"

#include <exception>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

int main(int argc, char** argv) {
  namespace pf = curvebench::property_families;
  if (argc > 2) {
    std::cerr << "usage: write_properties [document]\n";
    return 2;
  }
  const std::string path = argc == 2 ? argv[1] : pf::document_path();
  try {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::ostringstream text;
    text << in.rdbuf();
    const std::string updated = pf::with_table(text.str(), pf::markdown_table(pf::measure_all()));
    if (updated == text.str()) {
      std::cout << path << ": table unchanged\n";
      return 0;
    }
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << updated;
    if (!out) throw std::runtime_error("cannot write " + path);
    std::cout << path << ": table rewritten\n";
  } catch (const std::exception& e) {
    std::cerr << "write_properties: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
