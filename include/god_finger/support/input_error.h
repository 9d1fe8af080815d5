// Error type for bad input given to god_finger at load or configuration time (mesh files,
// mesh data, parameters). The message is one line meant for the user: it names the input
// (file, parameter, vertex...) and what is wrong with it. Never thrown from the 1 kHz path.
#pragma once

#include <stdexcept>
#include <string>

namespace god_finger
{
class InputError : public std::runtime_error
{
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

// The one-line message of a parameter out of its range:
// "parameter 'NAME' = VALUE is out of range RANGE (UNIT)".
std::string outOfRange(const char* name, double value, const char* range, const char* unit);
}  // namespace god_finger
