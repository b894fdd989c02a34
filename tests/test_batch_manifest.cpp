// The batch's manifest and messages (src/io/batch_manifest.*, batch_messages.*): rows that
// cross processes come back as they were, whatever bytes their fields hold; a manifest's
// cut line is skipped; a rerun resumes only inputs whose bytes and options hash as before.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.hpp"
#include "io/batch_manifest.hpp"
#include "io/batch_messages.hpp"

namespace molsurf {
namespace {

TEST(BatchManifest, RowsAndJobsRoundTrip) {
  io::BatchRow row;
  row.input = "dir with space/a\tb\n,\"c\".pdb";
  row.hash = "0123456789abcdef";
  row.status = "failed";
  row.message = std::string("line 1\nline\t2 \xff\0 end", 19);
  row.seconds = 0.1 + 0.2;
  row.atoms = 271860;
  row.cavities = -1;
  row.area = 974515.5611794359;
  row.volume = -0.0;
  const auto back = io::batch_result_from_bytes(io::batch_result_bytes(7, row));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->first, 7u);
  EXPECT_EQ(back->second.input, row.input);
  EXPECT_EQ(back->second.message, row.message);
  EXPECT_EQ(back->second.status, row.status);
  EXPECT_EQ(back->second.hash, row.hash);
  EXPECT_EQ(back->second.seconds, row.seconds);
  EXPECT_EQ(back->second.atoms, row.atoms);
  EXPECT_EQ(back->second.cavities, row.cavities);
  EXPECT_EQ(back->second.area, row.area);
  EXPECT_TRUE(std::signbit(back->second.volume));
  // The summary of a row that crossed processes is the row's own.
  EXPECT_EQ(io::batch_summary_csv({back->second}), io::batch_summary_csv({row}));
  EXPECT_EQ(io::batch_summary_jsonl({back->second}), io::batch_summary_jsonl({row}));

  const io::BatchJob job{3, "a:b 12:x", "1crn-2"};
  const auto job_back = io::batch_job_from_bytes(io::batch_job_bytes(job));
  ASSERT_TRUE(job_back);
  EXPECT_EQ(job_back->index, 3u);
  EXPECT_EQ(job_back->input, job.input);
  EXPECT_EQ(job_back->name, job.name);
  // Bytes cut short or from elsewhere are refused, not guessed.
  const std::string bytes = io::batch_result_bytes(7, row);
  EXPECT_FALSE(io::batch_result_from_bytes(bytes.substr(0, bytes.size() - 1)));
  EXPECT_FALSE(io::batch_result_from_bytes("R7:garbage"));
  EXPECT_FALSE(io::batch_job_from_bytes(bytes));
}

TEST(BatchManifest, ResumeFromAManifest) {
  testing::TempDir dir;
  const auto a = dir.path() / "a.pdb", b = dir.path() / "b.pdb", c = dir.path() / "c.pdb";
  std::ofstream(a) << "a";
  std::ofstream(b) << "b";
  std::ofstream(c) << "c";
  const std::vector<std::filesystem::path> inputs{a, b, c, a};
  EXPECT_EQ(io::batch_result_names(inputs), (std::vector<std::string>{"a", "b", "c", "a-2"}));
  io::BatchResume first = io::resume_batch(inputs, "--probe 1.2", {}, false);
  EXPECT_EQ(first.pending, (std::vector<std::size_t>{0, 1, 2, 3}));
  io::BatchRow ok;
  ok.status = "ok";
  ok.atoms = 3;
  ok.area = 1.5;
  io::BatchRow failed;
  failed.status = "failed";
  failed.message = "bad\tinput";
  io::record_batch_result(first.rows[0], ok);
  io::record_batch_result(first.rows[1], failed);
  EXPECT_EQ(first.rows[0].input, a.string());  // the input and hash stay
  EXPECT_EQ(first.rows[0].hash, io::batch_hash(a, "--probe 1.2"));
  {
    std::ofstream manifest(dir.path() / "manifest.tsv");
    manifest << io::batch_manifest_line(first.rows[0]) << io::batch_manifest_line(first.rows[1]) << "cut\tok\t1";
  }
  const auto read = io::read_batch_manifest(dir.path() / "manifest.tsv");
  EXPECT_EQ(read.size(), 2u);
  // a (twice) is done, b failed (skipped unless retried), c not run.
  EXPECT_EQ(io::resume_batch(inputs, "--probe 1.2", read, false).pending, (std::vector<std::size_t>{2}));
  EXPECT_EQ(io::resume_batch(inputs, "--probe 1.2", read, true).pending, (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(io::resume_batch(inputs, "--probe 1.4", read, false).pending, (std::vector<std::size_t>{0, 1, 2, 3}));
  std::ofstream(a) << "changed";
  EXPECT_EQ(io::resume_batch(inputs, "--probe 1.2", read, false).pending, (std::vector<std::size_t>{0, 2, 3}));
}

}  // namespace
}  // namespace molsurf
