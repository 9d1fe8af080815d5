// The last force a held-force driver gets is zero (src/ros/zero_on_stop.h), on the stops that
// never reach a destructor: Ctrl-C (SIGINT, handed on afterwards to the handler that was there:
// here the default, which ends the process) and a crash (SIGSEGV: the zeros first, then the
// signal's own end). Each in a child process (a death test, forked: this process starts no thread
// before it): the zero it sends is a file written.
#include "zero_on_stop.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace god_finger
{
namespace
{
std::string temporaryFile()
{
  char path[] = "/tmp/zero_on_stop_XXXXXX";
  close(mkstemp(path));
  return path;
}

std::string contents(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::remove(path.c_str());
  return text.str();
}

// Registers two zeros (one taken back), then gets `number`; waits for its end, at most 5 s (an
// alarm ends it otherwise, which the test reports as the wrong signal).
void stopBy(int number, const std::string& path)
{
  registerZeroOnStop([path]() { std::ofstream(path, std::ios::app) << "zero "; });
  unregisterZeroOnStop(registerZeroOnStop([path]() { std::ofstream(path, std::ios::app) << "unregistered "; }));
  alarm(5);
  raise(number);
  for (;;)
  {
    pause();  // the hook's thread hands the signal on, which ends this process
  }
}

TEST(ZeroOnStop, CtrlCSendsTheZerosThenHandsTheSignalOn)
{
  const std::string path = temporaryFile();
  EXPECT_EXIT(stopBy(SIGINT, path), ::testing::KilledBySignal(SIGINT), "");
  EXPECT_EQ(contents(path), "zero ");
}

TEST(ZeroOnStop, ACrashSendsTheZerosBeforeItEnds)
{
  const std::string path = temporaryFile();
  EXPECT_EXIT(stopBy(SIGSEGV, path), ::testing::KilledBySignal(SIGSEGV), "");
  EXPECT_EQ(contents(path), "zero ");
}
}  // namespace
}  // namespace god_finger
