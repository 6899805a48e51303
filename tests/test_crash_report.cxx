// The command-line tools' crash report (lkapp::installCrashReport): a fatal
// signal names the tool and the signal and prints the call stack on standard
// error, the lines printed before it are not lost in a pipe, and the tool
// still dies of that signal (a caller sees the crash).
#include "common/AppSupport.h"

#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace
{

/// This test program run again as a tool that crashes with `signal` after a
/// line on standard output; both streams into one pipe. Returns what it
/// wrote, and its wait status in `status`.
std::string runCrashingTool(int signal, int& status, const char* notes = "")
{
  int ends[2];
  if (pipe(ends) != 0)
    return "pipe failed";
  const pid_t child = fork();
  if (child == 0)
  {
    dup2(ends[1], STDOUT_FILENO);
    dup2(ends[1], STDERR_FILENO);
    close(ends[0]);
    close(ends[1]);
    const std::string number = std::to_string(signal);
    execl("/proc/self/exe", "test_apps", "--crash-probe", number.c_str(), notes, static_cast<char*>(nullptr));
    _exit(127);
  }
  close(ends[1]);
  std::string text;
  char buffer[4096];
  ssize_t n = 0;
  while ((n = read(ends[0], buffer, sizeof(buffer))) > 0)
    text.append(buffer, static_cast<std::size_t>(n));
  close(ends[0]);
  waitpid(child, &status, 0);
  return text;
}

TEST(CrashReport, ASegmentationFaultNamesTheToolAndPrintsTheStack)
{
  int status = 0;
  const std::string text = runCrashingTool(SIGSEGV, status);
  ASSERT_TRUE(WIFSIGNALED(status)) << text;
  EXPECT_EQ(WTERMSIG(status), SIGSEGV);
  EXPECT_NE(text.find("latticekit-probe: crashed (signal 11, SIGSEGV, a bad memory access); the call stack:\n"),
    std::string::npos)
    << text;
  EXPECT_NE(text.find("crashProbe"), std::string::npos) << "the stack names the function that crashed:\n" << text;
}

TEST(CrashReport, TheLinesPrintedBeforeTheCrashAreKept)
{
  // Standard output is a pipe here, which stdio would buffer whole: without
  // line buffering the line would be lost with the process.
  int status = 0;
  const std::string text = runCrashingTool(SIGSEGV, status);
  EXPECT_EQ(text.rfind("a line before the crash\n\nlatticekit-probe: crashed", 0), 0u) << text;
}

TEST(CrashReport, AnAbortIsReportedToo)
{
  int status = 0;
  const std::string text = runCrashingTool(SIGABRT, status);
  ASSERT_TRUE(WIFSIGNALED(status)) << text;
  EXPECT_EQ(WTERMSIG(status), SIGABRT);
  EXPECT_NE(text.find("latticekit-probe: crashed (signal 6, SIGABRT)"), std::string::npos) << text;
}

TEST(CrashReport, TheLastNoteIsPrintedAfterTheStack)
{
  // The probe sets "first", then "second": the report ends with the second.
  int status = 0;
  const std::string text = runCrashingTool(SIGSEGV, status, "first|second");
  ASSERT_TRUE(WIFSIGNALED(status)) << text;
  const auto stack = text.find("the call stack:\n");
  ASSERT_NE(stack, std::string::npos) << text;
  const std::string last = "latticekit-probe: second\n";
  ASSERT_GE(text.size(), last.size()) << text;
  EXPECT_EQ(text.substr(text.size() - last.size()), last) << text;
  EXPECT_EQ(text.find("first"), std::string::npos) << text;
}

TEST(CrashReport, AnEmptyNoteRemovesTheNote)
{
  int status = 0;
  const std::string text = runCrashingTool(SIGABRT, status, "kept somewhere|");
  ASSERT_TRUE(WIFSIGNALED(status)) << text;
  EXPECT_EQ(text.find("kept somewhere"), std::string::npos) << text;
}

TEST(CrashReport, ALongNoteIsCutNotOverrun)
{
  int status = 0;
  const std::string text = runCrashingTool(SIGSEGV, status, std::string(10000, 'x').c_str());
  ASSERT_TRUE(WIFSIGNALED(status)) << text;
  const auto at = text.find("latticekit-probe: xxx");
  ASSERT_NE(at, std::string::npos) << text.substr(0, 2000);
  const auto end = text.find('\n', at);
  ASSERT_NE(end, std::string::npos);
  EXPECT_EQ(end - at, 4095u); // the buffer, less its newline
}

} // namespace

/// The tool the tests run: exported, so that the stack can name it.
extern "C" __attribute__((noinline)) void crashProbe(int signal, const std::string& notes)
{
  lkapp::installCrashReport("latticekit-probe");
  // "a|b": set note a, then b (an empty part removes the note).
  if (!notes.empty())
    for (std::size_t from = 0;;)
    {
      const auto bar = notes.find('|', from);
      lkapp::setCrashNote(notes.substr(from, bar == std::string::npos ? std::string::npos : bar - from));
      if (bar == std::string::npos)
        break;
      from = bar + 1;
    }
  std::printf("a line before the crash\n");
  std::raise(signal);
  std::fflush(stdout); // not reached; keeps raise from being a tail call, so this frame shows
}

int main(int argc, char** argv)
{
  if (argc >= 3 && std::strcmp(argv[1], "--crash-probe") == 0)
  {
    crashProbe(std::atoi(argv[2]), argc > 3 ? argv[3] : "");
    return 0;
  }
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
