// Atomic output: the target holds either its old content or the complete new one, and no
// temporary survives a success, a failure or an abandoned write.
#include "stcontact/io/atomic_file.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>

#include <stdexcept>

#include "io/scratch_dir.hpp"
#include "stcontact/io/output_error.hpp"

namespace stc {
namespace {

using iotest::readFile;
using iotest::ScratchDir;
using iotest::writePlainFile;
using Names = std::vector<std::string>;

/// The OutputError thrown by `action`, or a test failure if none is thrown.
template <typename Action>
std::string outputErrorOf(Action action) {
  try {
    action();
  } catch (const OutputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no OutputError thrown";
  return {};
}

TEST(WriteFileAtomically, CreatesFileWithExactBytes) {
  ScratchDir dir;
  const std::string content("a,b\n1,2\0tail without newline", 29);
  writeFileAtomically(dir / "out.csv", content);
  EXPECT_EQ(readFile(dir / "out.csv"), content);
  EXPECT_EQ(dir.names(), Names{"out.csv"});
}

TEST(WriteFileAtomically, ReplacesExistingFileAndLeavesNoTemporaries) {
  ScratchDir dir;
  writePlainFile(dir / "out.csv", "old content that is longer than the new one\n");
  writeFileAtomically(dir / "out.csv", "new\n");
  EXPECT_EQ(readFile(dir / "out.csv"), "new\n");
  EXPECT_EQ(dir.names(), Names{"out.csv"});
}

TEST(WriteFileAtomically, WritesContentLargerThanItsBuffer) {
  ScratchDir dir;
  std::string content;
  for (int i = 0; content.size() < (1u << 20); ++i) content += std::to_string(i) + '\n';
  writeFileAtomically(dir / "big.txt", content);
  EXPECT_EQ(readFile(dir / "big.txt"), content);
}

TEST(WriteFileAtomically, ThrowsOutputErrorNamingPathUnderARegularFile) {
  ScratchDir dir;
  writePlainFile(dir / "somefile", "x");
  const auto target = dir / "somefile" / "child.csv";
  const std::string message = outputErrorOf([&] { writeFileAtomically(target, "data"); });
  EXPECT_NE(message.find(target.string()), std::string::npos) << message;
  EXPECT_NE(message.find("Not a directory"), std::string::npos) << message;
  EXPECT_EQ(dir.names(), Names{"somefile"});
  EXPECT_EQ(readFile(dir / "somefile"), "x");
}

TEST(WriteFileAtomically, ThrowsOutputErrorNamingPathInAMissingFolder) {
  ScratchDir dir;
  const auto target = dir / "missing" / "child.csv";
  const std::string message = outputErrorOf([&] { writeFileAtomically(target, "data"); });
  EXPECT_NE(message.find(target.string()), std::string::npos) << message;
  EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
  EXPECT_TRUE(dir.names().empty());
}

TEST(WriteFileAtomically, ThrowsAndRemovesTemporaryWhenTargetIsAFolder) {
  ScratchDir dir;
  std::filesystem::create_directories(dir / "taken" / "inside");
  const std::string message = outputErrorOf([&] { writeFileAtomically(dir / "taken", "data"); });
  EXPECT_NE(message.find((dir / "taken").string()), std::string::npos) << message;
  EXPECT_EQ(dir.names(), Names{"taken"});
}

TEST(AtomicFile, LeavesNoFileWhenNotCommitted) {
  ScratchDir dir;
  {
    AtomicFile file(dir / "out.csv");
    file.stream() << "partial";
  }
  EXPECT_TRUE(dir.names().empty());
}

TEST(AtomicFile, LeavesOldFileIntactWhenNotCommitted) {
  ScratchDir dir;
  writePlainFile(dir / "out.csv", "old\n");
  {
    AtomicFile file(dir / "out.csv");
    file.stream() << std::string(200000, 'n');  // more than the buffer: really on disk
  }
  EXPECT_EQ(readFile(dir / "out.csv"), "old\n");
  EXPECT_EQ(dir.names(), Names{"out.csv"});
}

TEST(AtomicFile, RemovesTemporaryWhenAnExceptionUnwinds) {
  ScratchDir dir;
  try {
    AtomicFile file(dir / "out.csv");
    file.stream() << "half a row,";
    throw std::runtime_error("solver failed mid-write");
  } catch (const std::runtime_error&) {
  }
  EXPECT_TRUE(dir.names().empty());
}

TEST(AtomicFile, WritesToAHiddenTemporaryInTheSameFolderUntilCommit) {
  ScratchDir dir;
  AtomicFile file(dir / "out.csv");
  file.stream() << "step,t\n0,0\n";
  const auto temporary = file.temporaryPath();
  EXPECT_EQ(temporary.parent_path(), dir.path());
  EXPECT_EQ(temporary.filename().string().rfind(".out.csv.tmp.", 0), 0u) << temporary;
  EXPECT_TRUE(std::filesystem::exists(temporary));
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));
  file.commit();
  EXPECT_EQ(readFile(dir / "out.csv"), "step,t\n0,0\n");
  EXPECT_EQ(dir.names(), Names{"out.csv"});
}

TEST(AtomicFile, GivesEachConcurrentWriterItsOwnTemporary) {
  ScratchDir dir;
  AtomicFile first(dir / "out.csv");
  AtomicFile second(dir / "out.csv");
  EXPECT_NE(first.temporaryPath(), second.temporaryPath());
  first.stream() << "first";
  second.stream() << "second";
  first.commit();
  second.commit();
  EXPECT_EQ(readFile(dir / "out.csv"), "second");
  EXPECT_EQ(dir.names(), Names{"out.csv"});
}

TEST(AtomicFile, CommittingTwiceIsALogicError) {
  ScratchDir dir;
  AtomicFile file(dir / "out.csv");
  file.commit();
  EXPECT_THROW(file.commit(), std::logic_error);
  EXPECT_THROW(file.stream(), std::logic_error);
  EXPECT_EQ(readFile(dir / "out.csv"), "");
}

TEST(AtomicFile, MoveHandsTheTemporaryToTheNewOwner) {
  ScratchDir dir;
  AtomicFile first(dir / "out.csv");
  first.stream() << "moved";
  AtomicFile second(std::move(first));
  second.commit();
  EXPECT_EQ(readFile(dir / "out.csv"), "moved");
  EXPECT_EQ(dir.names(), Names{"out.csv"});
}

/// Lowers the file-size limit (RLIMIT_FSIZE) so that writes fail with EFBIG, as on a full disk;
/// SIGXFSZ is ignored so the process survives. Both are restored on destruction.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &saved_);
    previousHandler_ = signal(SIGXFSZ, SIG_IGN);
    rlimit lowered = saved_;
    lowered.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &lowered);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &saved_);
    signal(SIGXFSZ, previousHandler_);
  }

 private:
  rlimit saved_{};
  sighandler_t previousHandler_;
};

TEST(AtomicFile, ThrowsOutputErrorAndRemovesTemporaryWhenAWriteFails) {
  ScratchDir dir;
  writePlainFile(dir / "out.csv", "old\n");
  std::string message;
  {
    FileSizeLimit limit(4096);
    message =
        outputErrorOf([&] { writeFileAtomically(dir / "out.csv", std::string(1 << 20, 'x')); });
  }
  EXPECT_NE(message.find((dir / "out.csv").string()), std::string::npos) << message;
  EXPECT_NE(message.find("File too large"), std::string::npos) << message;
  EXPECT_EQ(readFile(dir / "out.csv"), "old\n");
  EXPECT_EQ(dir.names(), Names{"out.csv"});
}

TEST(EnsureWritableDirectory, CreatesMissingParentsAndLeavesNoProbe) {
  ScratchDir dir;
  const auto out = dir / "results" / "hemicylinder" / "fas-apriori";
  ensureWritableDirectory(out);
  EXPECT_TRUE(std::filesystem::is_directory(out));
  EXPECT_TRUE(std::filesystem::is_empty(out));
}

TEST(EnsureWritableDirectory, AcceptsAnExistingFolderAndKeepsItsFiles) {
  ScratchDir dir;
  writePlainFile(dir / "keep.csv", "1\n");
  ensureWritableDirectory(dir.path());
  EXPECT_EQ(dir.names(), Names{"keep.csv"});
}

TEST(EnsureWritableDirectory, ThrowsNamingAFolderBelowARegularFile) {
  ScratchDir dir;
  writePlainFile(dir / "somefile", "x");
  const auto out = dir / "somefile" / "child";
  const std::string message = outputErrorOf([&] { ensureWritableDirectory(out); });
  EXPECT_NE(message.find(out.string()), std::string::npos) << message;
  EXPECT_EQ(dir.names(), Names{"somefile"});
}

TEST(EnsureWritableDirectory, ThrowsWhenThePathIsARegularFile) {
  ScratchDir dir;
  writePlainFile(dir / "somefile", "x");
  const std::string message = outputErrorOf([&] { ensureWritableDirectory(dir / "somefile"); });
  EXPECT_NE(message.find((dir / "somefile").string()), std::string::npos) << message;
  EXPECT_EQ(readFile(dir / "somefile"), "x");
}

}  // namespace
}  // namespace stc
