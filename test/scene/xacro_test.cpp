// Xacro files load as ROS's xacro expands them (xacro.h): properties and expressions, macros
// with defaults and block parameters, if / unless, includes by relative path and $(find),
// arguments' defaults; a xacro object file loads as a scene, through a scene list, and placed
// as spawn_object places it. Every refusal names the file, the element and the problem.
#include "god_finger/scene/xacro.h"
#include "god_finger/scene/scene_file.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace god_finger
{
namespace
{
class XacroTest : public ::testing::Test
{
 protected:
  XacroTest()
  {
    std::string pattern = (std::filesystem::temp_directory_path() / "god_finger_xacro_XXXXXX").string();
    folder_ = mkdtemp(pattern.data());
  }
  ~XacroTest() override
  {
    std::filesystem::remove_all(folder_);
  }

  std::string write(const std::string& name, const std::string& text) const
  {
    const std::string path = folder_ + "/" + name;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    std::ofstream(path) << text;
    return path;
  }

  std::string expand(const std::string& body) const
  {
    const std::string path = write("t.urdf.xacro", robot(body));
    std::ifstream stream(path);
    const std::string xml((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
    return expandXacro(xml, path, PackageResolver());
  }

  std::string refusal(const std::string& body) const
  {
    try
    {
      expand(body);
    }
    catch (const InputError& error)
    {
      return error.what();
    }
    return "(no error)";
  }

  static std::string robot(const std::string& body)
  {
    return "<?xml version='1.0'?><robot name='r' xmlns:xacro='http://www.ros.org/wiki/xacro'>" + body + "</robot>";
  }

  std::string folder_;
};

// The same object as a plain URDF and as xacro (a box whose size and mass are properties, its
// inertia by a macro): the same body.
const char* const kBoxXacro = R"(
  <xacro:property name="side" value="0.04"/>
  <xacro:property name="mass" value="${0.5 * 0.4}"/>
  <xacro:macro name="box_inertia" params="m s">
    <inertia ixx="${m * s * s / 6}" iyy="${m * s * s / 6}" izz="${m * s * s / 6}" ixy="0" ixz="0" iyz="0"/>
  </xacro:macro>
  <xacro:macro name="block" params="name size *origin">
    <link name="${name}">
      <inertial><mass value="${mass}"/><xacro:box_inertia m="${mass}" s="${size}"/></inertial>
      <collision><xacro:insert_block name="origin"/><geometry><box size="${size} ${size} ${size}"/></geometry></collision>
    </link>
  </xacro:macro>
  <xacro:block name="cube" size="${side}"><origin xyz="0 0 ${side / 2}"/></xacro:block>
)";

TEST_F(XacroTest, PropertiesExpressionsAndMacrosExpandToTheURDF)
{
  const std::string xml = expand(kBoxXacro);
  EXPECT_NE(xml.find("<link name=\"cube\">"), std::string::npos) << xml;
  EXPECT_NE(xml.find("<mass value=\"0.2\"/>"), std::string::npos) << xml;
  EXPECT_NE(xml.find("ixx=\"5.333333333333334e-05\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("<origin xyz=\"0 0 0.02\"/>"), std::string::npos) << xml;
  EXPECT_NE(xml.find("<box size=\"0.04 0.04 0.04\"/>"), std::string::npos) << xml;
  EXPECT_EQ(xml.find("xacro"), std::string::npos) << xml;
}

TEST_F(XacroTest, AnObjectFileInXacroLoadsAsItsURDFDoes)
{
  const std::string path = write("cube.urdf.xacro", robot(kBoxXacro));
  const SceneDescription scene = loadScene(path);
  ASSERT_EQ(scene.bodies.size(), 1u);
  const BodyDescription& cube = scene.bodies[0];
  EXPECT_EQ(cube.name, "cube");
  EXPECT_DOUBLE_EQ(cube.mass, 0.2);
  EXPECT_EQ(cube.geometry.kind, GeometryKind::kBox);
  EXPECT_DOUBLE_EQ(cube.geometry.size.x(), 0.04);
  EXPECT_NEAR(cube.inertia(0, 0), 0.2 * 0.04 * 0.04 / 6, 1e-15);

  // Through a scene list and placed as spawn_object places it.
  const std::string list = write("list.yaml", "objects:\n  - file: cube.urdf.xacro\n    xyz: [0.1, 0, 0]\n");
  const SceneDescription listed = loadScene(list);
  ASSERT_EQ(listed.bodies.size(), 2u);  // the table and the cube
  EXPECT_EQ(listed.bodies[1].name, "cube");
  ObjectPlacement placement;
  placement.name = "spawned";
  placement.pose.translation() = Eigen::Vector3d(0.0, 0.2, 0.0);
  const SceneDescription placed = loadPlacedObject(path, placement);
  ASSERT_EQ(placed.bodies.size(), 1u);
  EXPECT_EQ(placed.bodies[0].name, "spawned");
}

TEST_F(XacroTest, TheShippedXacroStoolIsTheURDFStool)
{
  const SceneDescription urdf = loadScene(std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/objects/stool.urdf");
  const SceneDescription xacro = loadScene(std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/objects/stool.urdf.xacro");
  ASSERT_EQ(urdf.bodies.size(), 1u);
  ASSERT_EQ(xacro.bodies.size(), 1u);
  const BodyDescription& a = urdf.bodies[0];
  const BodyDescription& b = xacro.bodies[0];
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.mass, b.mass);
  EXPECT_EQ(a.geometry.size, b.geometry.size);
  EXPECT_TRUE(a.collision_origin.isApprox(b.collision_origin, 1e-15));
  ASSERT_EQ(a.more_parts.size(), 4u);
  ASSERT_EQ(b.more_parts.size(), 4u);
  for (std::size_t i = 0; i < a.more_parts.size(); ++i)
  {
    EXPECT_TRUE(a.more_parts[i].geometry.size.isApprox(b.more_parts[i].geometry.size, 1e-15)) << i;
    EXPECT_TRUE(a.more_parts[i].origin.isApprox(b.more_parts[i].origin, 1e-15)) << i;
  }
  EXPECT_EQ(a.material.friction, b.material.friction);
}

TEST_F(XacroTest, IfUnlessArgumentsAndIncludes)
{
  // A package of ours ($(find) finds it by its package.xml above the file), a file in it to include.
  write("pkg/package.xml", "<package><name>my_objects</name></package>");
  write("pkg/parts/leg.xacro", robot(R"X(<xacro:macro name="leg" params="n x"><link name="leg${n}">
      <collision><geometry><cylinder radius="0.01" length="0.1"/></geometry></collision></link>
      <joint name="j${n}" type="fixed"><parent link="world"/><child link="leg${n}"/><origin xyz="${x} 0 0"/></joint>
      </xacro:macro>)X"));
  write("pkg/parts/near.xacro", robot(R"(<xacro:property name="near" value="0.05"/>)"));
  const std::string path = write("pkg/table.urdf.xacro", robot(R"X(
      <xacro:arg name="legs" default="2"/>
      <xacro:property name="legs" value="$(arg legs)"/>
      <xacro:include filename="$(find my_objects)/parts/leg.xacro"/>
      <xacro:include filename="parts/near.xacro"/>
      <link name="world"/>
      <xacro:leg n="1" x="${near}"/>
      <xacro:if value="${legs > 1}"><xacro:leg n="2" x="${-near}"/></xacro:if>
      <xacro:unless value="${legs > 1}"><link name="never"/></xacro:unless>
      <xacro:if value="false"><link name="never_either"/></xacro:if>
      )X"));
  const SceneDescription scene = loadScene(path);
  ASSERT_EQ(scene.bodies.size(), 2u);
  EXPECT_EQ(scene.bodies[0].name, "leg1");
  EXPECT_EQ(scene.bodies[1].name, "leg2");
  EXPECT_NEAR(scene.bodies[0].pose.translation().x(), 0.05, 1e-12);
  EXPECT_NEAR(scene.bodies[1].pose.translation().x(), -0.05, 1e-12);
}

TEST_F(XacroTest, ExpressionValues)
{
  const std::string xml = expand(R"(<xacro:property name="a" value="3"/><xacro:property name="s" value="abc"/>
      <t v1="${a ** 2 + 7 // 2 - 5 % 3}" v2="${radians(180) == pi}" v3="${max(a, 4) * -1}"
         v4="${s + 'd'}" v5="${not a > 2 or False}" v6="$${literal}" v7="${atan2(1, 1) * 4 / pi}"/>)");
  EXPECT_NE(xml.find("v1=\"10\""), std::string::npos) << xml;  // 9 + 3 - 2
  EXPECT_NE(xml.find("v2=\"True\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("v3=\"-4\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("v4=\"abcd\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("v5=\"False\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("v6=\"${literal}\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("v7=\"1\""), std::string::npos) << xml;
}

TEST_F(XacroTest, EveryRefusalNamesTheFileTheElementAndTheProblem)
{
  const std::string file = "xacro '" + folder_ + "/t.urdf.xacro': ";
  EXPECT_EQ(refusal("<link name='${missing}'/>"), file + "<link name='${missing}'> (line 1): no property 'missing'");
  EXPECT_EQ(refusal("<xacro:nothing/>"),
            file +
                "<xacro:nothing> (line 1): not a macro defined before it, nor one of xacro:property, arg, macro, "
                "include, if, unless, insert_block (the xacro this loader expands)");
  EXPECT_EQ(refusal("<xacro:macro name='m' params='a'/><xacro:m/>"),
            file + "<xacro:m> (line 1): macro 'm': parameter 'a' not given");
  EXPECT_EQ(refusal("<xacro:macro name='m' params='a'/><xacro:m a='1' b='2'/>"),
            file + "<xacro:m> (line 1): macro 'm' has no parameter 'b'");
  EXPECT_EQ(refusal("<t v='${1 +}'/>"), file + "<t> (line 1): expression '1 +': ends where a value was expected");
  EXPECT_EQ(refusal("<t v='${1 / 0}'/>"), file + "<t> (line 1): expression '1 / 0': division by zero");
  EXPECT_EQ(refusal("<t v='${unknown(1)}'/>"),
            file + "<t> (line 1): expression 'unknown(1)': no function unknown() in this xacro subset");
  EXPECT_EQ(refusal("<t v='${'yes' if True else 'no'}'/>").substr(0, file.size()), file);
  EXPECT_EQ(refusal("<t v='$(arg x)'/>"),
            file + "<t> (line 1): $(arg x): no <xacro:arg name='x' default=.../> before it");
  EXPECT_EQ(refusal("<xacro:arg name='x'/>"),
            file + "<xacro:arg name='x'> (line 1): an argument without a default (a scene file takes no arguments)");
  EXPECT_EQ(refusal("<t v='$(eval 1)'/>"),
            file +
                "<t> (line 1): $(eval 1): not one of $(find PKG), $(arg NAME), $(env NAME), $(optenv NAME "
                "[DEFAULT]), $(dirname)");
  EXPECT_EQ(refusal("<xacro:if value='maybe'/>"), file + "<xacro:if> (line 1): value 'maybe' is not true or false");
  EXPECT_EQ(refusal("<xacro:include filename='none.xacro'/>"),
            file + "<xacro:include> (line 1): '" + folder_ +
                "/none.xacro': no such file, not a regular file, empty or over 64 MB");
  EXPECT_EQ(refusal("<xacro:include filename='/dev/zero'/>"),
            file + "<xacro:include> (line 1): '/dev/zero': no such file, not a regular file, empty or over 64 MB");
  // Macros each calling the next twice: 2^20 calls, refused past 100,000.
  std::string doubling = "<xacro:macro name='m0' params=''><link name='l'/></xacro:macro>";
  for (int i = 1; i <= 20; ++i)
  {
    doubling += "<xacro:macro name='m" + std::to_string(i) + "' params=''><xacro:m" + std::to_string(i - 1) +
                "/><xacro:m" + std::to_string(i - 1) + "/></xacro:macro>";
  }
  const std::string too_many = refusal(doubling + "<xacro:m20/>");
  EXPECT_EQ(too_many.substr(0, file.size()), file);
  EXPECT_EQ(too_many.substr(too_many.size() - 35), "more than 100000 macro calls in all") << too_many;
  EXPECT_EQ(refusal("<xacro:include filename='t.urdf.xacro'/>"),
            file + "<xacro:include> (line 1): '" + folder_ + "/t.urdf.xacro' includes itself");
  EXPECT_EQ(refusal("<xacro:macro name='m' params=''><xacro:m/></xacro:macro><xacro:m/>"),
            file + "macros and includes nested deeper than 50 (a macro calling itself?)");
  EXPECT_EQ(refusal("<xacro:insert_block name='b'/>"),
            file + "<xacro:insert_block name='b'> (line 1): no block 'b' (a block property or a * parameter)");
  EXPECT_EQ(refusal("<xacro:property value='1'/>"), file + "<xacro:property> (line 1): needs the attribute 'name'");
  EXPECT_EQ(refusal("<t v=\"${'open}\"/>"), file + "<t> (line 1): expression ''open': a string is not closed");

  // A scene that is not XML: the loader's message names the file.
  const std::string broken = write("broken.xacro", "<robot xmlns:xacro='x'><link");
  try
  {
    loadScene(broken);
    ADD_FAILURE() << "a broken xacro file loaded";
  }
  catch (const InputError& error)
  {
    const std::string expected = "xacro '" + broken + "': not XML: ";
    EXPECT_EQ(std::string(error.what()).substr(0, expected.size()), expected);
  }
}
}  // namespace
}  // namespace god_finger
