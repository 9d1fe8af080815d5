#include "god_finger/scene/xacro.h"

#include "god_finger/support/input_error.h"

#include <tinyxml2.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <vector>

namespace god_finger
{
namespace
{
bool startsWith(const std::string& text, const std::string& prefix)
{
  return text.compare(0, prefix.size(), prefix) == 0;
}

bool endsWith(const std::string& text, const std::string& suffix)
{
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// A value of an expression: a number, a text or a truth value (Python's, as xacro's are).
struct Value
{
  enum class Kind
  {
    kNumber,
    kText,
    kBool
  };
  Kind kind = Kind::kNumber;
  double number = 0.0;
  std::string text;
  bool truth = false;

  static Value ofNumber(double v)
  {
    return Value{Kind::kNumber, v, {}, false};
  }
  static Value ofText(std::string t)
  {
    return Value{Kind::kText, 0.0, std::move(t), false};
  }
  static Value ofBool(bool b)
  {
    return Value{Kind::kBool, 0.0, {}, b};
  }
};

std::string formatNumber(double v)
{
  if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 1e15)
  {
    return std::to_string(static_cast<long long>(v));
  }
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

std::string toText(const Value& value)
{
  switch (value.kind)
  {
    case Value::Kind::kNumber:
      return formatNumber(value.number);
    case Value::Kind::kBool:
      return value.truth ? "True" : "False";
    case Value::Kind::kText:
      break;
  }
  return value.text;
}

// A property's text as a value: a number when all of it reads as one.
Value fromText(const std::string& text)
{
  const char* begin = text.data();
  const char* end = begin + text.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(*begin)))
  {
    ++begin;
  }
  while (end > begin && std::isspace(static_cast<unsigned char>(end[-1])))
  {
    --end;
  }
  double number = 0.0;
  if (begin < end)
  {
    const auto result = std::from_chars(begin, end, number);
    if (result.ec == std::errc() && result.ptr == end)
    {
      return Value::ofNumber(number);
    }
  }
  return Value::ofText(text);
}

// One ${...} expression, over properties looked up by `lookup`; throws std::runtime_error with
// the problem (the caller names the file and the element).
class Expression
{
 public:
  Expression(const std::string& text, std::function<std::string(const std::string&)> lookup)
      : text_(text), lookup_(std::move(lookup))
  {
  }

  Value evaluate()
  {
    Value value = orExpression();
    skipSpace();
    if (position_ != text_.size())
    {
      problem("unexpected '" + text_.substr(position_) + "'");
    }
    return value;
  }

 private:
  [[noreturn]] void problem(const std::string& what) const
  {
    throw std::runtime_error("expression '" + text_ + "': " + what);
  }

  void skipSpace()
  {
    while (position_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[position_])))
    {
      ++position_;
    }
  }

  bool take(const std::string& token)
  {
    skipSpace();
    if (text_.compare(position_, token.size(), token) != 0)
    {
      return false;
    }
    // A word operator ends at a word's end (`order` is a name, not `or` + `der`).
    const bool word = std::isalpha(static_cast<unsigned char>(token[0]));
    const std::size_t after = position_ + token.size();
    if (word && after < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[after])) || text_[after] == '_'))
    {
      return false;
    }
    position_ = after;
    return true;
  }

  static bool truthOf(const Value& value)
  {
    switch (value.kind)
    {
      case Value::Kind::kBool:
        return value.truth;
      case Value::Kind::kNumber:
        return value.number != 0.0;
      case Value::Kind::kText:
        break;
    }
    return !value.text.empty();
  }

  double numberOf(const Value& value) const
  {
    if (value.kind == Value::Kind::kBool)
    {
      return value.truth ? 1.0 : 0.0;
    }
    if (value.kind == Value::Kind::kText)
    {
      problem("'" + value.text + "' is not a number");
    }
    return value.number;
  }

  Value orExpression()
  {
    Value left = andExpression();
    while (take("or"))
    {
      const Value right = andExpression();
      left = truthOf(left) ? left : right;
    }
    return left;
  }

  Value andExpression()
  {
    Value left = notExpression();
    while (take("and"))
    {
      const Value right = notExpression();
      left = truthOf(left) ? right : left;
    }
    return left;
  }

  Value notExpression()
  {
    if (take("not"))
    {
      return Value::ofBool(!truthOf(notExpression()));
    }
    return comparison();
  }

  // `a op b` for op one of == != < > <= >= (Python compares strings and numbers alike).
  template <typename T>
  static bool compare(const std::string& op, const T& a, const T& b)
  {
    return op == "=="   ? a == b
           : op == "!=" ? a != b
           : op == "<"  ? a < b
           : op == ">"  ? a > b
           : op == "<=" ? a <= b
                        : a >= b;
  }

  Value comparison()
  {
    Value left = sum();
    for (;;)
    {
      std::string op;
      for (const char* candidate : {"==", "!=", "<=", ">=", "<", ">"})
      {
        if (take(candidate))
        {
          op = candidate;
          break;
        }
      }
      if (op.empty())
      {
        return left;
      }
      const Value right = sum();
      const bool as_text = left.kind == Value::Kind::kText || right.kind == Value::Kind::kText;
      const bool result =
          as_text ? compare(op, toText(left), toText(right)) : compare(op, numberOf(left), numberOf(right));
      left = Value::ofBool(result);
    }
  }

  Value sum()
  {
    Value left = term();
    for (;;)
    {
      if (take("+"))
      {
        const Value right = term();
        if (left.kind == Value::Kind::kText && right.kind == Value::Kind::kText)
        {
          left = Value::ofText(left.text + right.text);
        }
        else
        {
          left = Value::ofNumber(numberOf(left) + numberOf(right));
        }
      }
      else if (take("-"))
      {
        left = Value::ofNumber(numberOf(left) - numberOf(term()));
      }
      else
      {
        return left;
      }
    }
  }

  Value term()
  {
    Value left = unary();
    for (;;)
    {
      if (take("//"))
      {
        left = Value::ofNumber(std::floor(numberOf(left) / nonZero(numberOf(unary()))));
      }
      else if (take("*"))
      {
        left = Value::ofNumber(numberOf(left) * numberOf(unary()));
      }
      else if (take("/"))
      {
        left = Value::ofNumber(numberOf(left) / nonZero(numberOf(unary())));
      }
      else if (take("%"))
      {
        const double a = numberOf(left);
        const double b = nonZero(numberOf(unary()));
        left = Value::ofNumber(a - b * std::floor(a / b));  // Python's sign: the divisor's
      }
      else
      {
        return left;
      }
    }
  }

  double nonZero(double value) const
  {
    if (value == 0.0)
    {
      problem("division by zero");
    }
    return value;
  }

  Value unary()
  {
    if (take("-"))
    {
      return Value::ofNumber(-numberOf(unary()));
    }
    if (take("+"))
    {
      return Value::ofNumber(numberOf(unary()));
    }
    return power();
  }

  Value power()
  {
    Value base = atom();
    if (take("**"))
    {
      return Value::ofNumber(std::pow(numberOf(base), numberOf(unary())));
    }
    return base;
  }

  Value atom()
  {
    skipSpace();
    if (position_ >= text_.size())
    {
      problem("ends where a value was expected");
    }
    const char c = text_[position_];
    if (take("("))
    {
      Value inner = orExpression();
      if (!take(")"))
      {
        problem("a '(' is not closed");
      }
      return inner;
    }
    if (c == '\'' || c == '"')
    {
      const std::size_t end = text_.find(c, position_ + 1);
      if (end == std::string::npos)
      {
        problem("a string is not closed");
      }
      Value value = Value::ofText(text_.substr(position_ + 1, end - position_ - 1));
      position_ = end + 1;
      return value;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.')
    {
      double number = 0.0;
      const auto result = std::from_chars(text_.data() + position_, text_.data() + text_.size(), number);
      if (result.ec != std::errc())
      {
        problem("bad number at '" + text_.substr(position_) + "'");
      }
      position_ = result.ptr - text_.data();
      return Value::ofNumber(number);
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_')
    {
      std::size_t end = position_;
      while (end < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[end])) || text_[end] == '_'))
      {
        ++end;
      }
      const std::string name = text_.substr(position_, end - position_);
      position_ = end;
      if (take("("))
      {
        return call(name);
      }
      if (name == "True" || name == "true")
      {
        return Value::ofBool(true);
      }
      if (name == "False" || name == "false")
      {
        return Value::ofBool(false);
      }
      if (name == "pi")
      {
        return Value::ofNumber(M_PI);
      }
      if (name == "e")
      {
        return Value::ofNumber(M_E);
      }
      return fromText(lookup_(name));
    }
    problem("unexpected '" + text_.substr(position_) + "'");
  }

  Value call(const std::string& name)
  {
    std::vector<double> arguments;
    if (!take(")"))
    {
      do
      {
        arguments.push_back(numberOf(orExpression()));
      } while (take(","));
      if (!take(")"))
      {
        problem("the call of " + name + "() is not closed");
      }
    }
    static const std::map<std::string, double (*)(double)> one = {
        {"sin", [](double x) { return std::sin(x); }},         {"cos", [](double x) { return std::cos(x); }},
        {"tan", [](double x) { return std::tan(x); }},         {"asin", [](double x) { return std::asin(x); }},
        {"acos", [](double x) { return std::acos(x); }},       {"atan", [](double x) { return std::atan(x); }},
        {"sqrt", [](double x) { return std::sqrt(x); }},       {"exp", [](double x) { return std::exp(x); }},
        {"log", [](double x) { return std::log(x); }},         {"abs", [](double x) { return std::fabs(x); }},
        {"fabs", [](double x) { return std::fabs(x); }},       {"floor", [](double x) { return std::floor(x); }},
        {"ceil", [](double x) { return std::ceil(x); }},       {"radians", [](double x) { return x * M_PI / 180.0; }},
        {"degrees", [](double x) { return x * 180.0 / M_PI; }}};
    static const std::map<std::string, double (*)(double, double)> two = {
        {"atan2", [](double y, double x) { return std::atan2(y, x); }},
        {"pow", [](double x, double y) { return std::pow(x, y); }},
        {"min", [](double x, double y) { return std::min(x, y); }},
        {"max", [](double x, double y) { return std::max(x, y); }}};
    if (const auto f = one.find(name); f != one.end())
    {
      if (arguments.size() != 1)
      {
        problem(name + "() takes 1 argument");
      }
      return Value::ofNumber(f->second(arguments[0]));
    }
    if (const auto f = two.find(name); f != two.end())
    {
      if (arguments.size() != 2)
      {
        problem(name + "() takes 2 arguments");
      }
      return Value::ofNumber(f->second(arguments[0], arguments[1]));
    }
    problem("no function " + name + "() in this xacro subset");
  }

  std::string text_;
  std::size_t position_ = 0;
  std::function<std::string(const std::string&)> lookup_;
};

// Names in one macro call, or the file's top level (parent null).
struct Scope
{
  const Scope* parent = nullptr;
  std::map<std::string, std::string> values;
  std::map<std::string, tinyxml2::XMLElement*> blocks;  // block properties: their content's holder

  const std::string* value(const std::string& name) const
  {
    for (const Scope* scope = this; scope != nullptr; scope = scope->parent)
    {
      if (const auto found = scope->values.find(name); found != scope->values.end())
      {
        return &found->second;
      }
    }
    return nullptr;
  }

  tinyxml2::XMLElement* block(const std::string& name) const
  {
    for (const Scope* scope = this; scope != nullptr; scope = scope->parent)
    {
      if (const auto found = scope->blocks.find(name); found != scope->blocks.end())
      {
        return found->second;
      }
    }
    return nullptr;
  }
};

struct MacroParameter
{
  std::string name;
  enum class Kind
  {
    kValue,
    kBlock,     // *name: one element
    kContents,  // **name: an element's children
  } kind = Kind::kValue;
  bool has_default = false;
  std::string default_text;
};

struct Macro
{
  std::vector<MacroParameter> parameters;
  tinyxml2::XMLElement* body = nullptr;  // in the expander's storage
  std::string file;
};

std::string canonical(const std::string& path)
{
  std::error_code error;
  const std::filesystem::path result = std::filesystem::weakly_canonical(path, error);
  return error ? path : result.string();
}

// A regular file's text, "" when it is none or not readable (never a device or a pipe: an
// include of /dev/zero must not read forever); larger than kMaxIncludeBytes: refused by the caller.
constexpr std::uintmax_t kMaxIncludeBytes = 64u << 20;

std::string readFile(const std::string& path)
{
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error) || std::filesystem::file_size(path, error) > kMaxIncludeBytes)
  {
    return {};
  }
  std::ifstream stream(path);
  if (!stream.good())
  {
    return {};
  }
  std::stringstream content;
  content << stream.rdbuf();
  return content.str();
}

class Expander
{
 public:
  explicit Expander(const PackageResolver& packages) : packages_(packages) {}

  std::string run(const std::string& xml, const std::string& path)
  {
    if (document_.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS || document_.RootElement() == nullptr)
    {
      throw InputError("xacro '" + path + "': not XML: " +
                       std::string(document_.ErrorStr() != nullptr ? document_.ErrorStr() : "no root element"));
    }
    Scope top;
    includes_.insert(canonical(path));
    tinyxml2::XMLElement* root = document_.RootElement();
    substituteAttributes(root, top, path);
    processChildren(root, &top, path, 0);
    root->DeleteAttribute("xmlns:xacro");
    tinyxml2::XMLPrinter printer;
    document_.Print(&printer);
    return printer.CStr();
  }

 private:
  [[noreturn]] static void fail(const std::string& file, const std::string& where, const std::string& problem)
  {
    throw InputError("xacro '" + file + "': " + (where.empty() ? "" : where + ": ") + problem);
  }

  static std::string describe(const tinyxml2::XMLElement* element)
  {
    std::string text = std::string("<") + element->Name();
    if (const char* name = element->Attribute("name"))
    {
      text += std::string(" name='") + name + "'";
    }
    return text + "> (line " + std::to_string(element->GetLineNum()) + ")";
  }

  static std::string attribute(const tinyxml2::XMLElement* element, const char* name, const std::string& file)
  {
    const char* value = element->Attribute(name);
    if (value == nullptr)
    {
      fail(file, describe(element), std::string("needs the attribute '") + name + "'");
    }
    return value;
  }

  // $(...) substitution arguments and ${...} expressions in one text.
  std::string evaluateText(const std::string& text, const Scope& scope, const std::string& file,
                           const std::string& where)
  {
    std::string out;
    std::size_t i = 0;
    while (i < text.size())
    {
      if (text.compare(i, 3, "$${") == 0)
      {
        out += "${";
        i += 3;
      }
      else if (text.compare(i, 2, "${") == 0)
      {
        const std::size_t end = text.find('}', i + 2);
        if (end == std::string::npos)
        {
          fail(file, where, "'${' without its '}' in '" + text + "'");
        }
        const std::string expression = text.substr(i + 2, end - i - 2);
        try
        {
          out += toText(Expression(expression,
                                   [&](const std::string& name)
                                   {
                                     const std::string* value = scope.value(name);
                                     if (value == nullptr)
                                     {
                                       throw std::runtime_error("no property '" + name + "'");
                                     }
                                     return *value;
                                   })
                            .evaluate());
        }
        catch (const std::runtime_error& error)
        {
          fail(file, where, error.what());
        }
        i = end + 1;
      }
      else if (text.compare(i, 2, "$(") == 0)
      {
        const std::size_t end = text.find(')', i + 2);
        if (end == std::string::npos)
        {
          fail(file, where, "'$(' without its ')' in '" + text + "'");
        }
        out += substitution(text.substr(i + 2, end - i - 2), file, where);
        i = end + 1;
      }
      else
      {
        out += text[i++];
      }
    }
    return out;
  }

  std::string substitution(const std::string& command, const std::string& file, const std::string& where)
  {
    std::istringstream words(command);
    std::string verb;
    std::string first;
    words >> verb >> first;
    std::string rest;
    std::getline(words, rest);
    rest.erase(0, rest.find_first_not_of(' '));
    if (verb == "find" && !first.empty())
    {
      std::string package;
      const std::string folder = resolveFileName("package://" + first + "/", folderOf(file), packages_, &package);
      if (folder.empty())
      {
        fail(file, where, "$(find " + first + "): no package '" + first + "' found");
      }
      return folder.back() == '/' ? folder.substr(0, folder.size() - 1) : folder;
    }
    if (verb == "arg" && !first.empty())
    {
      const auto found = arguments_.find(first);
      if (found == arguments_.end())
      {
        fail(file, where, "$(arg " + first + "): no <xacro:arg name='" + first + "' default=.../> before it");
      }
      return found->second;
    }
    if (verb == "env" && !first.empty())
    {
      const char* value = std::getenv(first.c_str());
      if (value == nullptr)
      {
        fail(file, where, "$(env " + first + "): not set");
      }
      return value;
    }
    if (verb == "optenv" && !first.empty())
    {
      const char* value = std::getenv(first.c_str());
      return value != nullptr ? std::string(value) : rest;
    }
    if (verb == "dirname" && first.empty())
    {
      return folderOf(file);
    }
    fail(file, where,
         "$(" + command + "): not one of $(find PKG), $(arg NAME), $(env NAME), $(optenv NAME [DEFAULT]), $(dirname)");
  }

  void substituteAttributes(tinyxml2::XMLElement* element, const Scope& scope, const std::string& file)
  {
    for (const tinyxml2::XMLAttribute* a = element->FirstAttribute(); a != nullptr; a = a->Next())
    {
      const std::string value = a->Value();
      if (value.find('$') != std::string::npos)
      {
        element->SetAttribute(a->Name(), evaluateText(value, scope, file, describe(element)).c_str());
      }
    }
  }

  // The children of `from` (a holder outside the document, or a removed element), expanded in
  // `scope`, put in place of `at` under `parent`; `at` is deleted.
  void spliceExpanded(tinyxml2::XMLElement* from, tinyxml2::XMLNode* parent, tinyxml2::XMLElement* at, Scope* scope,
                      const std::string& file, int depth)
  {
    tinyxml2::XMLElement* holder = document_.NewElement("holder");
    for (const tinyxml2::XMLNode* child = from->FirstChild(); child != nullptr; child = child->NextSibling())
    {
      holder->InsertEndChild(child->DeepClone(&document_));
    }
    processChildren(holder, scope, file, depth);
    tinyxml2::XMLNode* anchor = at;
    while (tinyxml2::XMLNode* child = holder->FirstChild())
    {
      parent->InsertAfterChild(anchor, child);
      anchor = child;
    }
    document_.DeleteNode(holder);
    parent->DeleteChild(at);
  }

  tinyxml2::XMLElement* store(const tinyxml2::XMLNode* content)
  {
    tinyxml2::XMLElement* holder = storage_.NewElement("block");
    storage_.InsertEndChild(holder);
    if (content != nullptr)
    {
      holder->InsertEndChild(content->DeepClone(&storage_));
    }
    return holder;
  }

  void processChildren(tinyxml2::XMLNode* parent, Scope* scope, const std::string& file, int depth)
  {
    if (depth > kMaxXacroDepth)
    {
      fail(file, "",
           "macros and includes nested deeper than " + std::to_string(kMaxXacroDepth) + " (a macro calling itself?)");
    }
    tinyxml2::XMLNode* node = parent->FirstChild();
    while (node != nullptr)
    {
      tinyxml2::XMLNode* next = node->NextSibling();
      if (tinyxml2::XMLElement* element = node->ToElement())
      {
        const std::string name = element->Name();
        if (startsWith(name, "xacro:"))
        {
          xacroElement(element, name.substr(6), parent, scope, file, depth);
        }
        else
        {
          substituteAttributes(element, *scope, file);
          processChildren(element, scope, file, depth);
        }
      }
      else if (tinyxml2::XMLText* text = node->ToText())
      {
        const std::string value = text->Value();
        if (value.find('$') != std::string::npos)
        {
          text->SetValue(evaluateText(value, *scope, file, "text '" + value + "'").c_str());
        }
      }
      node = next;
    }
  }

  void xacroElement(tinyxml2::XMLElement* element, const std::string& tag, tinyxml2::XMLNode* parent, Scope* scope,
                    const std::string& file, int depth)
  {
    const std::string where = describe(element);
    if (tag == "property")
    {
      const std::string name = attribute(element, "name", file);
      Scope* target = scope;
      if (const char* which = element->Attribute("scope"))
      {
        if (std::string(which) == "global")
        {
          while (target->parent != nullptr)
          {
            target = const_cast<Scope*>(target->parent);
          }
        }
        else if (std::string(which) == "parent" && target->parent != nullptr)
        {
          target = const_cast<Scope*>(target->parent);
        }
      }
      if (const char* value = element->Attribute("value"))
      {
        target->values[name] = evaluateText(value, *scope, file, where);
      }
      else if (element->FirstChildElement() != nullptr)
      {
        tinyxml2::XMLElement* holder = storage_.NewElement("block");
        storage_.InsertEndChild(holder);
        for (const tinyxml2::XMLNode* child = element->FirstChild(); child != nullptr; child = child->NextSibling())
        {
          holder->InsertEndChild(child->DeepClone(&storage_));
        }
        target->blocks[name] = holder;
      }
      else
      {
        fail(file, where, "needs a value='...' or content");
      }
      parent->DeleteChild(element);
    }
    else if (tag == "arg")
    {
      const std::string name = attribute(element, "name", file);
      if (arguments_.count(name) == 0)
      {
        const char* value = element->Attribute("default");
        if (value == nullptr)
        {
          fail(file, where, "an argument without a default (a scene file takes no arguments)");
        }
        arguments_[name] = evaluateText(value, *scope, file, where);
      }
      parent->DeleteChild(element);
    }
    else if (tag == "macro")
    {
      defineMacro(element, file);
      parent->DeleteChild(element);
    }
    else if (tag == "include")
    {
      include(element, parent, scope, file, depth);
    }
    else if (tag == "if" || tag == "unless")
    {
      const std::string value = evaluateText(attribute(element, "value", file), *scope, file, where);
      bool truth = false;
      if (value == "true" || value == "True" || value == "1")
      {
        truth = true;
      }
      else if (value != "false" && value != "False" && value != "0")
      {
        const Value number = fromText(value);
        if (number.kind != Value::Kind::kNumber)
        {
          fail(file, where, "value '" + value + "' is not true or false");
        }
        truth = number.number != 0.0;
      }
      if (truth == (tag == "if"))
      {
        spliceExpanded(element, parent, element, scope, file, depth);
      }
      else
      {
        parent->DeleteChild(element);
      }
    }
    else if (tag == "insert_block")
    {
      const std::string name = attribute(element, "name", file);
      tinyxml2::XMLElement* block = scope->block(name);
      if (block == nullptr)
      {
        fail(file, where, "no block '" + name + "' (a block property or a * parameter)");
      }
      spliceExpanded(block, parent, element, scope, file, depth);
    }
    else if (const auto macro = macros_.find(tag); macro != macros_.end())
    {
      callMacro(macro->first, macro->second, element, parent, scope, file, depth);
    }
    else
    {
      fail(file, where,
           "not a macro defined before it, nor one of xacro:property, arg, macro, include, if, unless, "
           "insert_block (the xacro this loader expands)");
    }
  }

  void defineMacro(const tinyxml2::XMLElement* element, const std::string& file)
  {
    const std::string name = attribute(element, "name", file);
    Macro macro;
    macro.file = file;
    std::istringstream words(element->Attribute("params") != nullptr ? element->Attribute("params") : "");
    std::string word;
    while (words >> word)
    {
      MacroParameter parameter;
      if (startsWith(word, "**"))
      {
        parameter.kind = MacroParameter::Kind::kContents;
        word = word.substr(2);
      }
      else if (startsWith(word, "*"))
      {
        parameter.kind = MacroParameter::Kind::kBlock;
        word = word.substr(1);
      }
      const std::size_t assign = word.find(":=");
      if (assign != std::string::npos)
      {
        parameter.has_default = true;
        parameter.default_text = word.substr(assign + 2);
        word = word.substr(0, assign);
        if (startsWith(parameter.default_text, "^"))
        {
          // ^|DEFAULT: the caller's property of that name, else DEFAULT (xacro's ^ form).
          parameter.default_text = parameter.default_text.substr(
              parameter.default_text.find('|') == std::string::npos ? 1 : parameter.default_text.find('|') + 1);
        }
      }
      parameter.name = word;
      macro.parameters.push_back(parameter);
    }
    macro.body = storage_.NewElement("macro");
    storage_.InsertEndChild(macro.body);
    for (const tinyxml2::XMLNode* child = element->FirstChild(); child != nullptr; child = child->NextSibling())
    {
      macro.body->InsertEndChild(child->DeepClone(&storage_));
    }
    macros_[name] = std::move(macro);
  }

  void callMacro(const std::string& name, const Macro& macro, tinyxml2::XMLElement* call, tinyxml2::XMLNode* parent,
                 Scope* scope, const std::string& file, int depth)
  {
    const std::string where = describe(call);
    auto local = std::make_unique<Scope>();
    local->parent = scope;
    std::set<std::string> known;
    const tinyxml2::XMLElement* next_block = call->FirstChildElement();
    for (const MacroParameter& parameter : macro.parameters)
    {
      known.insert(parameter.name);
      if (parameter.kind != MacroParameter::Kind::kValue)
      {
        if (next_block == nullptr)
        {
          fail(file, where, "macro '" + name + "': no element for its block parameter '" + parameter.name + "'");
        }
        tinyxml2::XMLElement* holder = storage_.NewElement("block");
        storage_.InsertEndChild(holder);
        if (parameter.kind == MacroParameter::Kind::kBlock)
        {
          holder->InsertEndChild(next_block->DeepClone(&storage_));
        }
        else
        {
          for (const tinyxml2::XMLNode* child = next_block->FirstChild(); child != nullptr;
               child = child->NextSibling())
          {
            holder->InsertEndChild(child->DeepClone(&storage_));
          }
        }
        // The block as the caller wrote it, expanded in the caller's scope when inserted there.
        local->blocks[parameter.name] = holder;
        next_block = next_block->NextSiblingElement();
        continue;
      }
      if (const char* given = call->Attribute(parameter.name.c_str()))
      {
        local->values[parameter.name] = evaluateText(given, *scope, file, where);
      }
      else if (parameter.has_default)
      {
        const std::string* inherited = scope->value(parameter.name);
        local->values[parameter.name] =
            inherited != nullptr ? *inherited : evaluateText(parameter.default_text, *scope, file, where);
      }
      else
      {
        fail(file, where, "macro '" + name + "': parameter '" + parameter.name + "' not given");
      }
    }
    for (const tinyxml2::XMLAttribute* a = call->FirstAttribute(); a != nullptr; a = a->Next())
    {
      if (known.count(a->Name()) == 0)
      {
        fail(file, where, "macro '" + name + "' has no parameter '" + a->Name() + "'");
      }
    }
    if (++expansions_ > kMaxXacroExpansions)
    {
      fail(file, where, "more than " + std::to_string(kMaxXacroExpansions) + " macro calls in all");
    }
    Scope* kept = local.get();
    scopes_.push_back(std::move(local));
    spliceExpanded(macro.body, parent, call, kept, macro.file, depth + 1);
  }

  void include(tinyxml2::XMLElement* element, tinyxml2::XMLNode* parent, Scope* scope, const std::string& file,
               int depth)
  {
    const std::string where = describe(element);
    const std::string filename = evaluateText(attribute(element, "filename", file), *scope, file, where);
    std::string package;
    const std::string path = resolveFileName(filename, folderOf(file), packages_, &package);
    if (path.empty())
    {
      fail(file, where, "'" + filename + "': no package '" + package + "' found");
    }
    if (includes_.count(canonical(path)) != 0)
    {
      fail(file, where, "'" + path + "' includes itself");
    }
    const std::string xml = readFile(path);
    if (xml.empty())
    {
      fail(file, where, "'" + path + "': no such file, not a regular file, empty or over 64 MB");
    }
    tinyxml2::XMLDocument included;
    if (included.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS || included.RootElement() == nullptr)
    {
      fail(path, "", "not XML: " + std::string(included.ErrorStr() != nullptr ? included.ErrorStr() : "no root"));
    }
    tinyxml2::XMLElement* holder = storage_.NewElement("include");
    storage_.InsertEndChild(holder);
    for (const tinyxml2::XMLNode* child = included.RootElement()->FirstChild(); child != nullptr;
         child = child->NextSibling())
    {
      holder->InsertEndChild(child->DeepClone(&storage_));
    }
    includes_.insert(canonical(path));
    spliceExpanded(holder, parent, element, scope, path, depth + 1);
    includes_.erase(canonical(path));
  }

  PackageResolver packages_;
  tinyxml2::XMLDocument document_;
  tinyxml2::XMLDocument storage_;  // macro bodies, blocks and included content
  std::map<std::string, Macro> macros_;
  std::map<std::string, std::string> arguments_;
  std::vector<std::unique_ptr<Scope>> scopes_;  // macro calls' scopes, alive while blocks refer to them
  std::set<std::string> includes_;              // the files being expanded (a cycle check)
  long expansions_ = 0;                         // macro calls so far (kMaxXacroExpansions)
};
}  // namespace

bool isXacro(const std::string& path, const std::string& xml)
{
  return endsWith(path, ".xacro") || xml.find("xmlns:xacro") != std::string::npos;
}

std::string expandXacro(const std::string& xml, const std::string& path, const PackageResolver& packages)
{
  return Expander(packages).run(xml, path);
}
}  // namespace god_finger
