// AtomicFile: a target is replaced whole or left alone, and no temporary is left behind.
#include <gtest/gtest.h>
#include <signal.h>
#include <stdlib.h>
#include <dirent.h>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/temporary_registry.hpp"
#include "molsurf/error.hpp"

namespace fs = std::filesystem;
using molsurf::AtomicFile;

namespace {

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "molsurf_atomic_XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::size_t entries() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
  }
  static std::string slurp(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  static void put(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }

  fs::path dir_;
};

TEST_F(AtomicFileTest, WritesAndCommits) {
  const fs::path target = dir_ / "out.txt";
  molsurf::write_file_atomically(target, "hello\n");
  EXPECT_EQ(slurp(target), "hello\n");
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, TemporaryIsBesideTargetAndHidden) {
  const fs::path target = dir_ / "x.vtp";
  AtomicFile file(target);
  EXPECT_EQ(file.temp_path().parent_path(), dir_);
  EXPECT_EQ(file.temp_path().filename().string().rfind(".x.vtp.tmp-", 0), 0u) << file.temp_path();
  EXPECT_TRUE(fs::exists(file.temp_path()));
  EXPECT_FALSE(fs::exists(target));
}

TEST_F(AtomicFileTest, TwoWritersOfOneTargetGetDistinctTemporaries) {
  AtomicFile first(dir_ / "t");
  AtomicFile second(dir_ / "t");
  EXPECT_NE(first.temp_path(), second.temp_path());
}

TEST_F(AtomicFileTest, MissingDirectoryThrowsWithNameAndReasonAndLeavesNothing) {
  const fs::path target = dir_ / "missing" / "x.vtp";
  try {
    molsurf::write_file_atomically(target, "data");
    FAIL() << "expected molsurf::Error";
  } catch (const molsurf::Error& error) {
    EXPECT_EQ(std::string(error.what()), target.string() + ": cannot write: No such file or directory");
  }
  EXPECT_FALSE(fs::exists(dir_ / "missing"));
  EXPECT_EQ(entries(), 0u);
}

TEST_F(AtomicFileTest, FailureMidWriteLeavesOldTargetAndNoTemporary) {
  const fs::path target = dir_ / "report.json";
  put(target, "old content");
  const auto produce = [](std::ostream& out) {
    out << "half of the new";
    throw std::runtime_error("producer failed");
  };
  EXPECT_THROW(
      {
        AtomicFile file(target);
        produce(file.stream());
        file.commit();
      },
      std::runtime_error);
  EXPECT_EQ(slurp(target), "old content");
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, UncommittedWriteLeavesNoTarget) {
  const fs::path target = dir_ / "never.txt";
  {
    AtomicFile file(target);
    file.write("data");
  }
  EXPECT_FALSE(fs::exists(target));
  EXPECT_EQ(entries(), 0u);
}

TEST_F(AtomicFileTest, OverwriteReplacesTheWholeFile) {
  const fs::path target = dir_ / "mesh.off";
  put(target, std::string(10000, 'x'));
  molsurf::write_file_atomically(target, "short");
  EXPECT_EQ(slurp(target), "short");
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, LibraryWritingToTempPathIsCommitted) {
  const fs::path target = dir_ / "lib.bin";
  AtomicFile file(target);
  put(file.temp_path(), "written by a library");
  file.commit();
  EXPECT_TRUE(file.committed());
  EXPECT_EQ(slurp(target), "written by a library");
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, RenameOntoADirectoryFailsAndCleansUp) {
  const fs::path target = dir_ / "occupied";
  fs::create_directory(target);
  fs::create_directory(target / "child");  // a non-empty directory cannot be replaced
  try {
    molsurf::write_file_atomically(target, "data");
    FAIL() << "expected molsurf::Error";
  } catch (const molsurf::Error& error) {
    EXPECT_EQ(std::string(error.what()).rfind(target.string() + ": cannot write: ", 0), 0u) << error.what();
  }
  EXPECT_TRUE(fs::is_directory(target));
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, ReadOnlyDirectoryThrows) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions";
  fs::permissions(dir_, fs::perms::owner_read | fs::perms::owner_exec);
  EXPECT_THROW(molsurf::write_file_atomically(dir_ / "x", "data"), molsurf::Error);
  fs::permissions(dir_, fs::perms::owner_all);
  EXPECT_EQ(entries(), 0u);
}

// ---- issue 12, item 4 ----------------------------------------------------------------

TEST_F(AtomicFileTest, SymbolicLinksDevicesAndDirectoriesAreNeverReplaced) {
  put(dir_ / "real.json", "keep");
  fs::create_symlink("real.json", dir_ / "link.json");
  fs::create_symlink("nowhere.json", dir_ / "dangling.json");
  for (const fs::path& target : {dir_ / "link.json", dir_ / "dangling.json"}) {
    try {
      molsurf::write_file_atomically(target, "data");
      FAIL() << "expected molsurf::Error for " << target;
    } catch (const molsurf::Error& error) {
      EXPECT_NE(std::string(error.what()).find("symbolic link"), std::string::npos) << error.what();
    }
    EXPECT_TRUE(fs::is_symlink(target));
  }
  EXPECT_EQ(slurp(dir_ / "real.json"), "keep");
  EXPECT_FALSE(fs::exists(dir_ / "nowhere.json"));
  try {
    molsurf::write_file_atomically("/dev/null", "data");
    FAIL() << "expected molsurf::Error for /dev/null";
  } catch (const molsurf::Error& error) {
    EXPECT_NE(std::string(error.what()).find("device"), std::string::npos) << error.what();
  }
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_EQ(entries(), 3u);  // no temporary left
}

TEST_F(AtomicFileTest, ASetReplacesItsTargetsOnlyWhenAllAreComplete) {
  put(dir_ / "a.vert", "old a");
  put(dir_ / "a.face", "old b");
  {
    molsurf::AtomicFileSet set;
    set.add(dir_ / "a.vert").write("new a");
    set.add(dir_ / "a.face");  // a writer that fails before finishing: the set is dropped
  }
  EXPECT_EQ(slurp(dir_ / "a.vert"), "old a");
  EXPECT_EQ(slurp(dir_ / "a.face"), "old b");
  EXPECT_EQ(entries(), 2u);

  molsurf::AtomicFileSet set;
  set.add(dir_ / "a.vert").write("new a");
  set.add(dir_ / "a.face").write("new b");
  set.add(dir_ / "c.json").write("new c");
  // The third target turns into a non-empty directory before the commit: the message
  // says which files were written and which not.
  fs::create_directories(dir_ / "c.json" / "child");
  try {
    set.commit();
    FAIL() << "expected molsurf::Error";
  } catch (const molsurf::Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("c.json: cannot write"), std::string::npos) << message;
    EXPECT_NE(message.find("already written: " + (dir_ / "a.vert").string() + ", " + (dir_ / "a.face").string()),
              std::string::npos)
        << message;
  }
}

// A process ended by any catchable signal in the middle of a write leaves no temporary.
TEST_F(AtomicFileTest, SignalsRemoveTemporaries) {
  for (int signal_number : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGXFSZ, SIGXCPU, SIGALRM, SIGUSR1, SIGUSR2,
                            SIGABRT, SIGVTALRM, SIGPROF}) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      const rlimit no_core{0, 0};
      ::setrlimit(RLIMIT_CORE, &no_core);  // SIGQUIT, SIGXFSZ, SIGABRT would dump one here
      molsurf::detail::remove_temporaries_on_signals();
      AtomicFile first(dir_ / "big.vtp");
      first.write(std::string(1 << 20, 'x'));
      AtomicFile second(dir_ / "report.json");
      second.write("half");
      ::raise(signal_number);
      ::_exit(0);  // not reached: the signal ends the process
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the signal must still end the process";
    EXPECT_EQ(WTERMSIG(status), signal_number);
    EXPECT_EQ(entries(), 0u) << "temporaries left after signal " << signal_number;
  }
}

// The signal handler removes a temporary by its directory's descriptor, so a path longer
// than PATH_MAX from the root (a deep working directory) is no exception.
TEST_F(AtomicFileTest, SignalsRemoveTemporariesUnderPathsDeeperThanPathMax) {
  const std::string component(200, 'd');
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    if (::chdir(dir_.c_str()) != 0) ::_exit(2);
    for (int depth = 0; depth < 25; ++depth)  // 25 * 201 bytes: beyond 4096
      if (::mkdir(component.c_str(), 0700) != 0 || ::chdir(component.c_str()) != 0) ::_exit(3);
    molsurf::detail::remove_temporaries_on_signals();
    AtomicFile file("deep.vtp");
    file.write("half");
    if (molsurf::detail::registered_temporaries() != 1) ::_exit(4);
    ::raise(SIGTERM);
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "child exited with " << WEXITSTATUS(status);
  // Walk down relative to each directory, as no absolute path reaches the bottom.
  int fd = ::open(dir_.c_str(), O_RDONLY | O_DIRECTORY);
  for (int depth = 0; depth < 25; ++depth) {
    const int next = ::openat(fd, component.c_str(), O_RDONLY | O_DIRECTORY);
    ::close(fd);
    ASSERT_GE(next, 0) << depth;
    fd = next;
  }
  DIR* bottom = ::fdopendir(fd);
  ASSERT_NE(bottom, nullptr);
  std::size_t left = 0;
  while (const dirent* entry = ::readdir(bottom)) {
    const std::string name = entry->d_name;
    left += name != "." && name != "..";
  }
  ::closedir(bottom);
  EXPECT_EQ(left, 0u) << "the temporary is still there";
  ASSERT_EQ(std::system(("rm -rf '" + (dir_ / component).string() + "'").c_str()), 0);  // deeper than remove_all goes
}

// A name of 246..255 bytes is legal, but ".NAME.tmp-PID-N" would not be: the temporary is
// then named by a hash, and the write succeeds.
TEST_F(AtomicFileTest, LongTargetNamesGetAShortTemporaryName) {
  for (std::size_t length : {200u, 245u, 246u, 251u, 255u}) {
    const fs::path target = dir_ / std::string(length, 'n');
    {
      AtomicFile file(target);
      const std::string temporary = file.temp_path().filename().string();
      EXPECT_LE(temporary.size(), 255u) << length;
      EXPECT_EQ(temporary.rfind(length < 240 ? "." + target.filename().string() + ".tmp-" : ".molsurf-", 0), 0u)
          << temporary;
      file.write("long");
      file.commit();
    }
    EXPECT_EQ(slurp(target), "long") << length;
    EXPECT_EQ(entries(), 1u) << length;
    fs::remove(target);
  }
  EXPECT_THROW(AtomicFile(dir_ / std::string(256, 'n')), molsurf::Error);
}

// What SIGKILL leaves (it cannot be caught) is removed by the next write of the same
// target, once the process in the name is gone; a live process's temporary is not.
TEST_F(AtomicFileTest, StaleTemporariesOfDeadProcessesAreRemoved) {
  const pid_t dead = ::fork();
  ASSERT_GE(dead, 0);
  if (dead == 0) ::_exit(0);
  ASSERT_EQ(::waitpid(dead, nullptr, 0), dead);  // reaped: the PID names no process now
  const std::string alive = std::to_string(::getppid());
  const std::string gone = std::to_string(dead);
  const std::string long_name(250, 'L');
  const std::vector<std::string> stale{".out.vtp.tmp-" + gone + "-0", ".out.vtp.tmp-" + gone + "-12"};
  const std::vector<std::string> kept{".out.vtp.tmp-" + alive + "-0",  // a live writer's
                                      ".other.vtp.tmp-" + gone + "-0",  // another target's
                                      ".out.vtp.tmp-" + gone + "-x",    // not our pattern
                                      ".out.vtp.tmp-" + gone};
  for (const std::string& name : stale) put(dir_ / name, "stale");
  for (const std::string& name : kept) put(dir_ / name, "kept");
  {
    AtomicFile file(dir_ / "out.vtp");
    file.write("new");
    file.commit();
  }
  for (const std::string& name : stale) EXPECT_FALSE(fs::exists(dir_ / name)) << name;
  for (const std::string& name : kept) EXPECT_TRUE(fs::exists(dir_ / name)) << name;
  // Hashed temporaries of long names too.
  {
    AtomicFile probe(dir_ / long_name);
    const std::string prefix = probe.temp_path().filename().string();
    put(dir_ / (prefix.substr(0, prefix.find(".tmp-") + 5) + gone + "-3"), "stale");
  }
  const std::size_t before = entries();
  molsurf::write_file_atomically(dir_ / long_name, "x");
  EXPECT_EQ(entries(), before) << "the long name's stale temporary was not removed (one file added, one removed)";
}

// A set lists a directory once, at its first file there (a .pvtp of thousands of pieces
// would read the directory once per piece), and still removes each of its targets' stale
// temporaries, and only theirs.
TEST_F(AtomicFileTest, ASetRemovesTheStaleTemporariesOfEachOfItsTargets) {
  const pid_t dead = ::fork();
  ASSERT_GE(dead, 0);
  if (dead == 0) ::_exit(0);
  ASSERT_EQ(::waitpid(dead, nullptr, 0), dead);
  const std::string gone = std::to_string(dead);
  std::vector<std::string> stale, kept;
  for (int k = 0; k < 50; ++k) stale.push_back(".s_" + std::to_string(k) + ".vtp.tmp-" + gone + "-0");
  kept.push_back(".s_50.vtp.tmp-" + gone + "-0");  // no file of the set
  for (const std::string& name : stale) put(dir_ / name, "stale");
  for (const std::string& name : kept) put(dir_ / name, "kept");
  molsurf::AtomicFileSet set;
  for (int k = 0; k < 50; ++k) set.add(dir_ / ("s_" + std::to_string(k) + ".vtp")).write("new");
  set.commit();
  for (const std::string& name : stale) EXPECT_FALSE(fs::exists(dir_ / name)) << name;
  for (const std::string& name : kept) EXPECT_TRUE(fs::exists(dir_ / name)) << name;
  EXPECT_EQ(entries(), 51u);
}

TEST_F(AtomicFileTest, RegistryForgetsCommittedAndRemovedTemporaries) {
  const int before = molsurf::detail::registered_temporaries();
  {
    AtomicFile kept(dir_ / "kept");
    AtomicFile dropped(dir_ / "dropped");
    EXPECT_EQ(molsurf::detail::registered_temporaries(), before + 2);
    kept.write("x");
    kept.commit();
    EXPECT_EQ(molsurf::detail::registered_temporaries(), before + 1);
  }
  EXPECT_EQ(molsurf::detail::registered_temporaries(), before);
}

}  // namespace
