#include "harness/writers.hpp"

#include "curvebench/core/error.hpp"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace curvebench::harness {

namespace fs = std::filesystem;

void write_atomic(const std::string& path, const std::string& text) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw invalid_input("--out " + path + ": is a directory, not a file");
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    if (!out) throw invalid_input("--out " + path + ": cannot be written (" + tmp + " cannot be created)");
    out << text;
    out.flush();
    if (!out) {
      out.close();
      fs::remove(tmp, ec);
      throw invalid_input("--out " + path + ": writing failed (disk full?)");
    }
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw invalid_input("--out " + path + ": cannot be written (" + ec.message() + ")");
  }
}

void check_results_path(const std::string& path) {
  if (path.empty()) throw invalid_input("--out: an empty path");
  const fs::path parent = fs::path(path).parent_path();
  std::error_code ec;
  fs::create_directories(parent.empty() ? fs::path(".") : parent, ec);
  if (ec) throw invalid_input("--out " + path + ": its directory cannot be created (" + ec.message() + ")");
  for (const std::string& p : {path, csv_path(path)}) {
    if (fs::is_directory(p, ec)) throw invalid_input("--out " + path + ": " + p + " is a directory, not a file");
    const std::string probe = p + ".tmp";
    const bool existed = fs::exists(probe, ec);
    {
      std::ofstream out(probe, std::ios::app);
      if (!out) throw invalid_input("--out " + path + ": " + p + " cannot be written");
    }
    if (!existed) fs::remove(probe, ec);
  }
}

std::string records_csv(const nlohmann::json& records) {
  std::ostringstream os;
  os << std::setprecision(17) << "case,group,quantity,method,setting,error,estimate,bounded,evaluations,status\n";
  const auto cell = [](const nlohmann::json& v) -> std::string {
    if (v.is_null()) return "";
    if (!v.is_string()) return v.dump();
    const std::string s = v.get<std::string>();
    if (s.find_first_of(",\"") == std::string::npos) return s;
    std::string quoted = "\"";
    for (char ch : s) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return quoted + "\"";
  };
  for (const auto& r : records)
    os << cell(r["case"]) << "," << cell(r["group"]) << "," << cell(r["quantity"]) << "," << cell(r["method"]) << ","
       << cell(r["setting"]) << "," << cell(r["error"]) << "," << cell(r["estimate"]) << "," << cell(r["bounded"])
       << "," << cell(r["evaluations"]) << "," << cell(r["status"]) << "\n";
  return os.str();
}

std::string csv_path(const std::string& json_path) {
  std::string p = json_path;
  if (p.size() > 5 && p.ends_with(".json")) p.resize(p.size() - 5);
  return p + ".csv";
}

void write_results(const nlohmann::json& results, const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::filesystem::create_directories(parent.empty() ? std::filesystem::path(".") : parent);
  write_atomic(path, results.dump(1) + "\n");
  write_atomic(csv_path(path), records_csv(results["records"]));
}

}  // namespace curvebench::harness
