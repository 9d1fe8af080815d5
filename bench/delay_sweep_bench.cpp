// Issue 29's delay sweep (scenarios/delay_sweep.h): every task x operator x round trip x jitter x
// loss, the passivity controller off and on, on simulated time (deterministic). One JSON line per
// trial on stdout; scripts/bench --delay keeps them and bench_report makes the report's section.
//   delay_sweep_bench
#include "god_finger/scenarios/delay_sweep.h"

#include <cstdio>

int main()
{
  for (const god_finger::DelayTrial& trial : god_finger::delaySweep())
  {
    std::printf("%s\n", god_finger::delayTrialJson(trial, god_finger::runDelayTrial(trial)).c_str());
  }
  return 0;
}
