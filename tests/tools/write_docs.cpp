// curvebench_docs [docs/specs.md]: rewrites docs/specs.md's spec section (between the families markers)
// from the family registry, io::families_markdown(). tests/test_registry.cpp fails until it is run
// after a registry entry changes. Exit status 0, or 1 with the reason on stderr.
#include "tools/families_section.hpp"

#include <exception>
#include <fstream>
#include <iostream>
#include <sstream>

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : "docs/specs.md";
  try {
    std::ifstream in(path);
    if (!in) throw curvebench::invalid_input(path + ": cannot be read");
    std::ostringstream text;
    text << in.rdbuf();
    const std::string updated = curvebench::docs::with_families_section(text.str());
    if (updated == text.str()) {
      std::cout << path << ": the families section is up to date\n";
      return 0;
    }
    std::ofstream out(path);
    if (!(out << updated)) throw curvebench::invalid_input(path + ": cannot be written");
    std::cout << path << ": families section rewritten from the registry\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "curvebench_docs: " << e.what() << "\n";
    return 1;
  }
}
