// Xacro files expanded into URDF, as ROS's xacro (the `xacro` command roslaunch users run)
// expands them, for the part of the language object and scene files use. Debian 12 ships no
// xacro, so the loader (urdf_scene.h: FILE.xacro, FILE.urdf.xacro, or any URDF whose <robot>
// declares xmlns:xacro) expands it itself:
//  - <xacro:property name value/> and block properties (<xacro:property name><origin/>...
//    </xacro:property>, used by <xacro:insert_block name/>); a property is evaluated where it is
//    defined (xacro evaluates lazily: a property may not use one defined after it);
//  - ${EXPRESSION} in attributes and text: numbers, 'strings', properties, + - * / // % **,
//    parentheses, comparisons, and / or / not, True / False, pi, e, and the math functions sin
//    cos tan asin acos atan atan2 sqrt exp log abs fabs floor ceil pow radians degrees min max;
//    $${ writes a literal ${;
//  - $(find PACKAGE), $(arg NAME) (its <xacro:arg name default/>: a scene file takes no
//    arguments), $(env NAME), $(optenv NAME [DEFAULT]), $(dirname) (the file's folder);
//  - <xacro:macro name params="a b:=1 *block **blocks"> and its calls <xacro:NAME a="..."> with
//    block parameters as child elements (*: one element; **: that element's children);
//  - <xacro:if value>, <xacro:unless value>; <xacro:include filename> (relative to the including
//    file, absolute, or $(find ...)), whose <robot>'s content is spliced in place.
//
// Errors: InputError, one line naming the file, the element and the problem: an xacro element
// or function this subset does not have, an undefined property, macro or argument, a bad
// expression, a macro parameter not given, an include that is missing, not a regular file, over
// 64 MB or includes itself, expansion deeper than kMaxXacroDepth or of more than
// kMaxXacroExpansions macro calls. Not real-time: reads files.
#pragma once

#include "god_finger/scene/urdf_scene.h"

#include <string>

namespace god_finger
{
// Deepest nesting of macro calls and includes (a macro calling itself stops here).
constexpr int kMaxXacroDepth = 50;
// Most macro calls in one expansion (macros that each call the next twice would otherwise
// double the output 50 times).
constexpr long kMaxXacroExpansions = 100000;

// Whether the file is xacro: its name ends in .xacro, or its text declares the xacro namespace.
bool isXacro(const std::string& path, const std::string& xml);

// The URDF text `xml` (read from `path`, which names it in errors and anchors relative
// includes) expands to.
std::string expandXacro(const std::string& xml, const std::string& path, const PackageResolver& packages);
}  // namespace god_finger
