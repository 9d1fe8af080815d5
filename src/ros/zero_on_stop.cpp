#include "zero_on_stop.h"

#include <ros/poll_manager.h>
#include <semaphore.h>
#include <signal.h>
#include <time.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <thread>

namespace god_finger
{
namespace
{
constexpr int kHandOn[] = {SIGINT, SIGTERM, SIGHUP};
constexpr int kCrash[] = {SIGSEGV, SIGBUS, SIGFPE, SIGABRT};

struct Hook
{
  std::mutex mutex;
  std::map<int, std::function<void()>> zeros;
  int next_id = 0;
  sem_t signalled;
  std::atomic<int> signal_number{0};
  std::atomic<bool> zeros_sent{false};
  struct sigaction previous[NSIG];
};

Hook& hook()
{
  static Hook* instance = new Hook;  // never destroyed: a signal may come during exit
  return *instance;
}

void onSignal(int number)
{
  Hook& h = hook();
  int expected = 0;
  if (h.signal_number.compare_exchange_strong(expected, number))
  {
    sem_post(&h.signalled);
  }
  for (int crash : kCrash)
  {
    if (number == crash)
    {
      // Wait for the zeros (the hook's thread runs while this one is stopped here), then die as
      // the signal would have made us.
      for (int i = 0; i < 200 && !h.zeros_sent.load(); ++i)
      {
        const timespec millisecond{0, 1000000};
        nanosleep(&millisecond, nullptr);
      }
      signal(number, SIG_DFL);
      raise(number);
      return;
    }
  }
}

void handOn(int number)
{
  const struct sigaction& previous = hook().previous[number];
  if (previous.sa_handler == SIG_IGN)
  {
    return;
  }
  if (previous.sa_handler == SIG_DFL)
  {
    signal(number, SIG_DFL);
    raise(number);
    return;
  }
  if (previous.sa_flags & SA_SIGINFO)
  {
    siginfo_t info{};
    info.si_signo = number;
    previous.sa_sigaction(number, &info, nullptr);
  }
  else
  {
    previous.sa_handler(number);
  }
}

void watch()
{
  Hook& h = hook();
  while (sem_wait(&h.signalled) != 0)
  {
  }
  {
    std::lock_guard<std::mutex> lock(h.mutex);
    for (auto& [id, send_zero] : h.zeros)
    {
      send_zero();
    }
  }
  if (!h.zeros.empty())
  {
    waitForPublishes(0.15);
  }
  h.zeros_sent = true;
  const int number = h.signal_number.load();
  for (int hand_on : kHandOn)
  {
    if (number == hand_on)
    {
      handOn(number);
    }
  }
}

void install()
{
  Hook& h = hook();
  sem_init(&h.signalled, 0, 0);
  struct sigaction action
  {
  };
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  for (int number : kHandOn)
  {
    sigaction(number, &action, &h.previous[number]);
  }
  for (int number : kCrash)
  {
    sigaction(number, &action, &h.previous[number]);
  }
  std::thread(watch).detach();
}
}  // namespace

bool waitForPublishes(double timeout)
{
  struct Passes
  {
    std::mutex mutex;
    std::condition_variable passed;
    int count = 0;
  };
  auto passes = std::make_shared<Passes>();
  const ros::PollManagerPtr& poll = ros::PollManager::instance();
  boost::signals2::connection listener = poll->addPollThreadListener(
      [passes]()
      {
        std::lock_guard<std::mutex> lock(passes->mutex);
        ++passes->count;
        passes->passed.notify_all();
      });
  bool passed = false;
  {
    std::unique_lock<std::mutex> lock(passes->mutex);
    passed = passes->passed.wait_for(lock, std::chrono::duration<double>(timeout),
                                     [&passes]() { return passes->count >= 2; });
  }
  poll->removePollThreadListener(listener);
  return passed;
}

int registerZeroOnStop(std::function<void()> send_zero)
{
  static std::once_flag installed;
  std::call_once(installed, install);
  Hook& h = hook();
  std::lock_guard<std::mutex> lock(h.mutex);
  const int id = h.next_id++;
  h.zeros[id] = std::move(send_zero);
  return id;
}

void unregisterZeroOnStop(int id)
{
  Hook& h = hook();
  std::lock_guard<std::mutex> lock(h.mutex);
  h.zeros.erase(id);
}
}  // namespace god_finger
