// Whether a test asserts its timing floors: a rate, a latency, a bound on wall-clock time.
// Not in an instrumented build (scripts/sanitize: AddressSanitizer and UndefinedBehaviorSanitizer),
// which runs several times slower, so that a floor there says nothing about the code. A test
// skips only its timing assertion this way; everything else in it still runs and is checked.
#pragma once

namespace god_finger
{
namespace test
{
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kTimingFloorsChecked = false;  // GCC, -fsanitize=address
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kTimingFloorsChecked = false;  // clang, -fsanitize=address
#else
constexpr bool kTimingFloorsChecked = true;
#endif
#else
constexpr bool kTimingFloorsChecked = true;
#endif
}  // namespace test
}  // namespace god_finger
