// src/blocks/spilled_bytes: records written to an unnamed temporary file and read back.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "blocks/spilled_bytes.hpp"
#include "molsurf/error.hpp"

namespace molsurf::blocks {
namespace {

// TMPDIR set for one scope, restored after.
class TemporaryDirectory {
 public:
  explicit TemporaryDirectory(const std::string& dir) {
    if (const char* old = std::getenv("TMPDIR")) old_ = old;
    ::setenv("TMPDIR", dir.c_str(), 1);
  }
  ~TemporaryDirectory() {
    if (old_) ::setenv("TMPDIR", old_->c_str(), 1);
    else ::unsetenv("TMPDIR");
  }

 private:
  std::optional<std::string> old_;
};

TEST(SpilledBytes, RecordsComeBackAsWrittenInAnyOrder) {
  SpilledBytes disk;
  std::string big(3 << 20, '\0');
  for (std::size_t k = 0; k < big.size(); ++k) big[k] = static_cast<char>(k * 131 % 251);
  const std::string with_zeros("a\0b\0\0c", 6);
  disk.push(with_zeros);
  disk.push("");
  disk.push(big);
  ASSERT_EQ(disk.size(), 3u);
  EXPECT_EQ(disk.read(2), big);
  EXPECT_EQ(disk.read(0), with_zeros);
  EXPECT_EQ(disk.read(1), "");
  EXPECT_EQ(disk.read(2), big);
  EXPECT_THROW((void)disk.read(3), std::out_of_range);
}

TEST(SpilledBytes, LeavesNoFileBehindInTheTemporaryDirectory) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "molsurf-test-spilled-bytes";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  {
    const TemporaryDirectory tmp(dir.string());
    SpilledBytes disk;
    disk.push("seams");
    EXPECT_TRUE(std::filesystem::is_empty(dir));  // unnamed from the start
    EXPECT_EQ(disk.read(0), "seams");
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  std::filesystem::remove_all(dir);
}

TEST(SpilledBytes, AMissingTemporaryDirectoryIsOneClearError) {
  const TemporaryDirectory tmp("/nonexistent/molsurf-no-such-dir");
  try {
    SpilledBytes disk;
    FAIL() << "a temporary file in a missing directory";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("--blocks"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("temporary"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace molsurf::blocks
