// A run's output folder written whole or not at all (src/io/run_folder.hpp): a commit replaces the
// previous run as a whole, a run that stops early leaves the target as it was, a second writer and a
// folder holding other files are refused, and temporaries of killed runs are cleaned up.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "scratch_dir.hpp"
#include "stcontact/core/interruption.hpp"
#include "stcontact/io/output_error.hpp"
#include "stcontact/io/run_folder.hpp"

namespace {

using stc::iotest::ScratchDir;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

/// A complete run into `target` that writes `file` with `text`.
void run(const fs::path& target, const std::string& file, const std::string& text) {
  stc::RunFolder folder(target);
  stc::iotest::writePlainFile(folder.path() / file, text);
  folder.commit();
}

/// The message of the OutputError that opening a run folder on `target` throws ("" if none).
std::string refusal(const fs::path& target) {
  try {
    stc::RunFolder folder(target);
  } catch (const stc::OutputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RunFolder, ACommitReplacesThePreviousRunAsAWhole) {
  const ScratchDir dir;
  run(dir / "out", "a.csv", "first");
  run(dir / "out", "b.csv", "second");
  EXPECT_FALSE(fs::exists(dir / "out" / "a.csv"));  // nothing of the previous run is left
  EXPECT_EQ(stc::iotest::readFile(dir / "out" / "b.csv"), "second");
  EXPECT_TRUE(fs::exists(dir / "out" / stc::kRunMarker));
  EXPECT_THAT(dir.names(), ElementsAre("out"));  // no temporary, no lock left beside it
}

TEST(RunFolder, ARunThatStopsEarlyLeavesTheTargetAsItWas) {
  const ScratchDir dir;
  run(dir / "out", "a.csv", "first");
  {
    stc::RunFolder folder(dir / "out");
    stc::iotest::writePlainFile(folder.path() / "b.csv", "half");
  }  // no commit: an exception, a late input error
  EXPECT_EQ(stc::iotest::readFile(dir / "out" / "a.csv"), "first");
  EXPECT_FALSE(fs::exists(dir / "out" / "b.csv"));
  EXPECT_THAT(dir.names(), ElementsAre("out"));
}

TEST(RunFolder, AnInterruptedRunDoesNotCommit) {
  const ScratchDir dir;
  run(dir / "out", "a.csv", "first");
  {
    stc::RunFolder folder(dir / "out");
    stc::iotest::writePlainFile(folder.path() / "b.csv", "second");
    stc::requestInterruption(0);
    EXPECT_THROW(folder.commit(), stc::Interrupted);
    stc::clearInterruption();
  }
  EXPECT_EQ(stc::iotest::readFile(dir / "out" / "a.csv"), "first");
  EXPECT_THAT(dir.names(), ElementsAre("out"));
}

TEST(RunFolder, ASecondWriterIsRefused) {
  const ScratchDir dir;
  stc::RunFolder first(dir / "out");
  EXPECT_THAT(refusal(dir / "out"), HasSubstr("is being written by another run"));
}

TEST(RunFolder, AFolderWithOtherFilesIsRefusedAndKept) {
  const ScratchDir dir;
  fs::create_directories(dir / "mine");
  stc::iotest::writePlainFile(dir / "mine" / "notes.txt", "keep");
  EXPECT_THAT(refusal(dir / "mine"), HasSubstr("holds files that are not a run's"));
  EXPECT_EQ(stc::iotest::readFile(dir / "mine" / "notes.txt"), "keep");
  EXPECT_EQ(refusal(dir / "empty_is_fine"), "");
}

TEST(RunFolder, TemporariesOfKilledRunsAreRemoved) {
  const ScratchDir dir;
  const fs::path stale = dir / ".out.run-2147480000";  // no such process
  fs::create_directories(stale);
  stc::iotest::writePlainFile(stale / "a.csv", "killed");
  run(dir / "out", "b.csv", "next");
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_THAT(dir.names(), ElementsAre("out"));
}

// The marker lists the run's files; a file the run did not write, at the top or in a folder of the
// run, keeps the folder from being replaced, named, and is kept.
TEST(RunFolder, OnlyTheFilesTheMarkerListsAreReplaced) {
  const ScratchDir dir;
  {
    stc::RunFolder folder(dir / "out");
    stc::iotest::writePlainFile(folder.path() / "a.csv", "first");
    fs::create_directories(folder.path() / "vtu");
    stc::iotest::writePlainFile(folder.path() / "vtu" / "f.vtu", "frame");
    folder.commit();
  }
  EXPECT_THAT(stc::listedFiles(dir / "out"), ElementsAre("a.csv", "vtu/f.vtu"));
  stc::iotest::writePlainFile(dir / "out" / "vtu" / "mine.vtu", "keep");
  EXPECT_THAT(refusal(dir / "out"), HasSubstr("holds 'vtu/mine.vtu', which its run did not write"));
  EXPECT_EQ(stc::iotest::readFile(dir / "out" / "vtu" / "mine.vtu"), "keep");
  fs::remove(dir / "out" / "vtu" / "mine.vtu");
  run(dir / "out", "b.csv", "second");  // its own files alone: replaced
  EXPECT_EQ(stc::iotest::readFile(dir / "out" / "b.csv"), "second");
  EXPECT_THAT(dir.names(), ElementsAre("out"));  // a refused run left no lock
}

// A marker without the list (an older version's, or one made by hand) is no licence.
TEST(RunFolder, AMarkerWithoutItsListIsRefused) {
  const ScratchDir dir;
  fs::create_directories(dir / "old");
  stc::iotest::writePlainFile(dir / "old" / stc::kRunMarker, "written by stcontact; the next run replaces it\n");
  stc::iotest::writePlainFile(dir / "old" / "summary.json", "{}");
  EXPECT_THAT(refusal(dir / "old"), HasSubstr("holds a run marker without the list of the run's files"));
  EXPECT_TRUE(fs::exists(dir / "old" / "summary.json"));
  EXPECT_THAT(dir.names(), ElementsAre("old"));
}

// A symbolic link given as the target is followed: the folder it names gets the run, the link stays.
TEST(RunFolder, ASymbolicLinkIsFollowedNotReplaced) {
  const ScratchDir dir;
  fs::create_directories(dir / "real");
  fs::create_directory_symlink(dir / "real", dir / "link");
  run(dir / "link", "a.csv", "through the link");
  EXPECT_TRUE(fs::is_symlink(dir / "link"));
  EXPECT_EQ(stc::iotest::readFile(dir / "real" / "a.csv"), "through the link");
}
