// god_finger_contact: see contact_tool.h and the README.
#include "contact_tool.h"

#include <exception>
#include <iostream>

int main(int argc, char** argv)
{
  god_finger::ContactToolOptions options;
  const std::string error = god_finger::parseContactToolOptions(argc, argv, &options);
  if (!error.empty())
  {
    std::cerr << "god_finger_contact: " << error << "\n";
    return 2;
  }
  if (options.help)
  {
    std::cout << god_finger::contactToolUsage();
    return 0;
  }
  try
  {
    return god_finger::runContactTool(options, std::cout, std::cerr);
  }
  catch (const std::exception& exception)
  {
    std::cerr << "god_finger_contact: " << exception.what() << "\n";
    return 2;
  }
}
