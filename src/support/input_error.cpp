#include "god_finger/support/input_error.h"

#include <sstream>

namespace god_finger
{
std::string outOfRange(const char* name, double value, const char* range, const char* unit)
{
  std::ostringstream message;
  message << "parameter '" << name << "' = " << value << " is out of range " << range << " (" << unit << ")";
  return message.str();
}
}  // namespace god_finger
