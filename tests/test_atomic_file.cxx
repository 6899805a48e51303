// Files written whole or not at all (lkapp::writeFileAtomically,
// commitTemporaryFile): the new contents replace the old in one rename, a
// failed write (here past the file size limit, as on a full disk) leaves the
// earlier file as it was and no temporary file behind, a link's target is
// replaced, and the file keeps its permissions.
#include "common/AtomicFile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <dirent.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace
{

/// A fresh, empty folder for one test.
std::string freshFolder(const std::string& name)
{
  const std::string folder = std::string(LATTICEKIT_TEST_TMP) + "/atomic_" + name;
  std::system(("rm -rf '" + folder + "' && mkdir -p '" + folder + "'").c_str());
  return folder;
}

std::string contentsOf(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> namesIn(const std::string& folder)
{
  std::vector<std::string> names;
  if (DIR* dir = opendir(folder.c_str()))
  {
    while (dirent* entry = readdir(dir))
    {
      const std::string name = entry->d_name;
      if (name != "." && name != "..")
        names.push_back(name);
    }
    closedir(dir);
  }
  std::sort(names.begin(), names.end());
  return names;
}

TEST(AtomicFile, ReplacesTheContentsAndLeavesNothingElse)
{
  const std::string folder = freshFolder("replace");
  std::string error;
  ASSERT_TRUE(lkapp::writeFileAtomically(folder + "/plan.txt", "first plan\n", error)) << error;
  ASSERT_TRUE(lkapp::writeFileAtomically(folder + "/plan.txt", "second\n", error)) << error;
  EXPECT_EQ(contentsOf(folder + "/plan.txt"), "second\n");
  EXPECT_EQ(namesIn(folder), std::vector<std::string>{ "plan.txt" });
}

TEST(AtomicFile, AWriteRemovesWhatKilledRunsLeftOfTheSameFile)
{
  // A run killed by SIGKILL (the out-of-memory killer) cannot remove its
  // temporary file. The next write of the same file removes those whose
  // process is gone; a live process's, and other files', stay.
  const std::string folder = freshFolder("stale");
  const pid_t child = fork();
  if (child == 0)
    _exit(0);
  ASSERT_GT(child, 0);
  waitpid(child, nullptr, 0); // its PID now names no process
  const std::string dead = std::to_string(child), live = std::to_string(getppid());
  const std::vector<std::string> planted = { ".piece0.partial-" + dead + "-0.stl", ".piece0.partial-" + dead + "-7.stl",
    ".piece0.partial-" + live + "-0.stl", ".piece1.partial-" + dead + "-0.stl", ".piece0.partial-" + dead + "-0.vtp",
    ".piece0.partial-x-0.stl" };
  for (const std::string& name : planted)
    std::ofstream(folder + "/" + name) << "partial";
  std::string error;
  ASSERT_TRUE(lkapp::writeFileAtomically(folder + "/piece0.stl", "solid\n", error)) << error;
  std::vector<std::string> kept = { ".piece0.partial-" + dead + "-0.vtp", ".piece0.partial-" + live + "-0.stl",
    ".piece0.partial-x-0.stl", ".piece1.partial-" + dead + "-0.stl", "piece0.stl" };
  std::sort(kept.begin(), kept.end());
  EXPECT_EQ(namesIn(folder), kept);
}

TEST(AtomicFile, AFailedWriteKeepsTheEarlierFile)
{
  const std::string folder = freshFolder("failed");
  const std::string path = folder + "/session.json";
  std::string error;
  ASSERT_TRUE(lkapp::writeFileAtomically(path, "{ \"the\": \"session saved before\" }\n", error)) << error;
  // In a child, so that the file size limit binds no other test: 10,000
  // bytes past a limit of 4,096 fail as they would on a full disk.
  const pid_t child = fork();
  if (child == 0)
  {
    std::signal(SIGXFSZ, SIG_IGN); // as lkapp::installCrashReport does
    rlimit limit{ 4096, 4096 };
    setrlimit(RLIMIT_FSIZE, &limit);
    std::string reason;
    const bool written = lkapp::writeFileAtomically(path, std::string(10000, 'x'), reason);
    _exit(!written && reason == "cannot write '" + path + "': File too large" ? 0 : 1);
  }
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "the write did not fail with the reason";
  EXPECT_EQ(contentsOf(path), "{ \"the\": \"session saved before\" }\n");
  EXPECT_EQ(namesIn(folder), std::vector<std::string>{ "session.json" }) << "a temporary file was left";
}

TEST(AtomicFile, ReplacesALinksTargetAndKeepsItsPermissions)
{
  const std::string folder = freshFolder("link");
  std::string error;
  ASSERT_TRUE(lkapp::writeFileAtomically(folder + "/target.stl", "old", error)) << error;
  ASSERT_EQ(chmod((folder + "/target.stl").c_str(), 0640), 0);
  ASSERT_EQ(symlink("target.stl", (folder + "/link.stl").c_str()), 0);
  ASSERT_TRUE(lkapp::writeFileAtomically(folder + "/link.stl", "new", error)) << error;
  struct stat st;
  ASSERT_EQ(lstat((folder + "/link.stl").c_str(), &st), 0);
  EXPECT_TRUE(S_ISLNK(st.st_mode)) << "the link became a file";
  EXPECT_EQ(contentsOf(folder + "/target.stl"), "new");
  ASSERT_EQ(stat((folder + "/target.stl").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0640u);
}

TEST(AtomicFile, RefusesAFolderAndRemovesTheTemporaryFile)
{
  const std::string folder = freshFolder("folder");
  std::string error;
  ASSERT_EQ(mkdir((folder + "/out.vtp").c_str(), 0755), 0);
  EXPECT_FALSE(lkapp::writeFileAtomically(folder + "/out.vtp", "data", error));
  EXPECT_EQ(error, "cannot write '" + folder + "/out.vtp': Is a directory");
  // A writer's temporary file that cannot replace the target goes.
  const std::string temporary = lkapp::temporaryPathBeside(folder + "/out.vtp");
  ASSERT_EQ(temporary.rfind(folder + "/.out.partial-", 0), 0u) << temporary;
  ASSERT_EQ(temporary.substr(temporary.size() - 4), ".vtp") << temporary;
  std::ofstream(temporary) << "data";
  EXPECT_FALSE(lkapp::commitTemporaryFile(temporary, folder + "/out.vtp", error));
  EXPECT_EQ(namesIn(folder), std::vector<std::string>{ "out.vtp" });
}

} // namespace

TEST(AtomicFile, FileNamesAreCutIntoFolderStemAndExtension)
{
  // The temporary file's and the planner's kept session's names are made
  // from these parts: a dot in a folder or at a name's start is no extension.
  const auto check = [](const std::string& path, const std::string& folder, const std::string& stem,
                       const std::string& extension) {
    const lkapp::FileNameParts p = lkapp::splitFileName(path);
    EXPECT_EQ(p.folder, folder) << path;
    EXPECT_EQ(p.stem, stem) << path;
    EXPECT_EQ(p.extension, extension) << path;
  };
  check("planner_session.json", "", "planner_session", ".json");
  check("/tmp/a.b/session", "/tmp/a.b/", "session", "");
  check("out/.hidden", "out/", ".hidden", "");
  check("out/piece.0.stl", "out/", "piece.0", ".stl");
  const std::string temporary = lkapp::temporaryPathBeside("out/piece.stl");
  EXPECT_EQ(temporary.rfind("out/.piece.partial-", 0), 0u) << temporary;
  EXPECT_EQ(temporary.substr(temporary.size() - 4), ".stl") << temporary;
}
