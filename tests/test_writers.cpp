// The tool's input reader (harness/files.hpp): every input file is read in chunks
// up to a limit, so an endless device or a huge file is refused with its size named.
// The tool's output files (harness/writers.hpp): results are written only to a
// regular file or a new path, through a temporary file created exclusively beside it and renamed;
// a directory, a symbolic link, a FIFO or a device is refused by name and left as it was. Before
// this, `accuracy --out /dev/full` (as root) replaced the device with a 60 kB regular file.
#include "harness/files.hpp"
#include "harness/writers.hpp"

#include "support/fixtures.hpp"

#include "curvebench/core/error.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using curvebench::harness::check_output_path;
using curvebench::harness::check_results_path;
using curvebench::harness::read_input_file;
using curvebench::harness::write_atomic;
using curvebench::testing::invalid_input_of;
using ::testing::HasSubstr;

namespace {

// A fresh directory per test, removed after it.
class writers : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string name = (fs::temp_directory_path() / "curvebench_writers_XXXXXX").string();
    ASSERT_NE(::mkdtemp(name.data()), nullptr);
    dir = name;
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  [[nodiscard]] std::string at(const std::string& name) const { return (dir / name).string(); }
  // Every name in the directory: no temporary file may be left behind.
  [[nodiscard]] std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }
  fs::path dir;
};

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

TEST_F(writers, a_new_path_and_a_regular_file_are_written_whole_with_no_temporary_left) {
  const std::string p = at("results.json");
  write_atomic(p, "first\n");
  EXPECT_EQ(read(p), "first\n");
  write_atomic(p, "second\n");
  EXPECT_EQ(read(p), "second\n");
  EXPECT_EQ(names(), std::vector<std::string>{"results.json"});
  // The new file gets what the umask gives (mkstemp's own 0600 would hide results from others).
  const ::mode_t mask = ::umask(022);
  write_atomic(at("shared.json"), "x");
  ::umask(mask);
  EXPECT_EQ(fs::status(at("shared.json")).permissions() & fs::perms::all, static_cast<fs::perms>(0644));
}

TEST_F(writers, a_fifo_is_refused_and_left_a_fifo) {
  const std::string p = at("pipe");
  ASSERT_EQ(::mkfifo(p.c_str(), 0600), 0);
  EXPECT_THAT(invalid_input_of([&] { write_atomic(p, "x"); }),
              HasSubstr("--out " + p + ": is a FIFO; results are written only to a regular file or a new path"));
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(p)));
  EXPECT_EQ(names(), std::vector<std::string>{"pipe"});
}

TEST_F(writers, a_symbolic_link_is_refused_and_its_target_unchanged) {
  const std::string target = at("target.json"), link = at("link.json");
  write_atomic(target, "kept\n");
  fs::create_symlink(target, link);
  EXPECT_THAT(invalid_input_of([&] { write_atomic(link, "x", "--json-out"); }),
              HasSubstr("--json-out " + link + ": is a symbolic link"));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_EQ(read(target), "kept\n");
}

TEST_F(writers, a_directory_is_refused) {
  fs::create_directory(at("sub"));
  EXPECT_THAT(invalid_input_of([&] { write_atomic(at("sub"), "x"); }), HasSubstr(": is a directory"));
  EXPECT_TRUE(fs::is_directory(at("sub")));
}

// Only the check is run on a device: were it broken, write_atomic would replace /dev/null as root.
TEST(writers_devices, a_character_device_is_refused_by_the_check) {
  ASSERT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_THAT(invalid_input_of([] { check_output_path("/dev/null", "--out"); }),
              HasSubstr("--out /dev/null: is a character device"));
  EXPECT_THAT(invalid_input_of([] { check_output_path("", "--out"); }), HasSubstr("--out: an empty path"));
}

// accuracy's check before minutes of work: the JSON and the CSV beside it, neither opened.
TEST_F(writers, the_results_check_refuses_a_fifo_beside_and_leaves_nothing) {
  const std::string json = at("run.json");
  check_results_path(json);
  EXPECT_TRUE(names().empty());
  ASSERT_EQ(::mkfifo(at("run.csv").c_str(), 0600), 0);
  EXPECT_THAT(invalid_input_of([&] { check_results_path(json); }), HasSubstr(at("run.csv") + ": is a FIFO"));
  EXPECT_EQ(names(), std::vector<std::string>{"run.csv"});
}

TEST_F(writers, inputs_are_read_whole_up_to_their_limit_and_refused_past_it) {
  const std::string p = at("spec.json");
  write_atomic(p, std::string(3u << 20, 'x'));  // three chunks of the reader
  EXPECT_EQ(read_input_file(p).size(), std::size_t(3) << 20);
  EXPECT_EQ(read_input_file(p, "", std::size_t(3) << 20).size(), std::size_t(3) << 20);  // exactly the limit
  EXPECT_THAT(invalid_input_of([&] { (void)read_input_file(p, "thresholds ", std::size_t(1) << 20); }),
              HasSubstr("thresholds " + p + ": larger than 1 MiB (1048576 bytes), the limit for this input"));
  EXPECT_THAT(invalid_input_of([&] { (void)read_input_file(at("missing.json")); }),
              HasSubstr(at("missing.json") + ": cannot be read"));
  EXPECT_THAT(invalid_input_of([&] { (void)read_input_file(dir.string()); }),
              HasSubstr(": is a directory, not a file"));
  // An endless device stops at the limit (here 1 MiB: a few reads, not a memory-sized one).
  EXPECT_THAT(invalid_input_of([] { (void)read_input_file("/dev/zero", "", std::size_t(1) << 20); }),
              HasSubstr("/dev/zero: larger than 1 MiB"));
}

}  // namespace
