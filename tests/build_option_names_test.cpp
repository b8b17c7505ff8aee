// The names the tools take for search methods and shell kinds (core.h): every value's name reads
// back as that value, the names are the ones the command lines document, and anything else,
// including another case or a near miss, is refused.
#include <revolve/baselines.h>
#include <revolve/revolve.h>

#include <gtest/gtest.h>

#include <string>

namespace revolve {
namespace {

TEST(BuildOptionNamesTest, EveryMethodsNameReadsBackAsIt) {
  for (const Method method : {Method::mibit, Method::linear, Method::kajiya}) {
    EXPECT_EQ(methodNamed(methodName(method)), method) << methodName(method);
  }
  EXPECT_EQ(std::string(methodName(Method::mibit)), "mibit");
  EXPECT_EQ(std::string(methodName(Method::linear)), "linear");
  EXPECT_EQ(std::string(methodName(Method::kajiya)), "kajiya");
}

TEST(BuildOptionNamesTest, EveryShellKindsNameReadsBackAsIt) {
  for (const ShellKind shell : {ShellKind::cylinder, ShellKind::cone, ShellKind::hybrid}) {
    EXPECT_EQ(shellKindNamed(shellKindName(shell)), shell) << shellKindName(shell);
  }
  EXPECT_EQ(std::string(shellKindName(ShellKind::cylinder)), "cylinder");
  EXPECT_EQ(std::string(shellKindName(ShellKind::cone)), "cone");
  EXPECT_EQ(std::string(shellKindName(ShellKind::hybrid)), "hybrid");
}

TEST(BuildOptionNamesTest, UnknownNamesAreRefused) {
  for (const char* name : {"", "MIBIT", "kajya", "mesh", "embree-cone", "mibit ", "cylinder"}) {
    EXPECT_FALSE(methodNamed(name).has_value()) << '"' << name << '"';
  }
  for (const char* name : {"", "Cylinder", "cones", "hybird", "mibit", " cone"}) {
    EXPECT_FALSE(shellKindNamed(name).has_value()) << '"' << name << '"';
  }
}

}  // namespace
}  // namespace revolve
