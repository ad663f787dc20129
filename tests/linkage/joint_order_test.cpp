#include "reconfig/linkage/joint_order.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "linkage_test_util.h"
#include "reconfig/common/input_error.h"

namespace reconfig::linkage {
namespace {

TEST(JointOrder, JansenLegFollowsFigure2) {
  const Linkage linkage = test::example("jansen.json");
  const JointOrder order = order_joints(linkage);
  ASSERT_TRUE(order.symbolic());
  std::vector<std::string> sequence;
  for (const Rule& rule : order.rules) sequence.push_back(describe_rule(linkage, order, rule));
  const std::vector<std::string> expected = {
      "\"O\" fixed",
      "\"B\" fixed",
      "\"C\" turned by the motor about \"O\"",
      "(\"C\", \"B\") -> \"U\"",
      "\"E\" rigid with \"B\", \"U\"",
      "(\"C\", \"B\") -> \"L\"",
      "(\"L\", \"E\") -> \"F\"",
      "\"P\" rigid with \"F\", \"L\"",
  };
  EXPECT_EQ(sequence, expected);
}

TEST(JointOrder, EveryJointOnceAndInputsFirst) {
  for (const char* name : test::kExamples) {
    const Linkage linkage = test::example(name);
    const JointOrder order = order_joints(linkage);
    std::vector<int> seen(linkage.joints.size(), 0);
    for (const Rule& rule : order.rules) {
      if (rule.kind == RuleKind::kNewtonBlock) {
        const NewtonBlock& block = order.blocks[rule.block];
        for (const auto& link : block.links)
          for (int joint : {link.r0, link.r1})
            if (std::find(block.joints.begin(), block.joints.end(), joint) == block.joints.end()) {
              EXPECT_TRUE(seen[joint]) << name;
            }
        for (int joint : block.joints) ++seen[joint];
        continue;
      }
      if (rule.i >= 0) {
        EXPECT_TRUE(seen[rule.i]) << name;
      }
      if (rule.j >= 0) {
        EXPECT_TRUE(seen[rule.j]) << name;
      }
      ++seen[rule.k];
    }
    for (int count : seen) EXPECT_EQ(count, 1) << name;
  }
}

TEST(JointOrder, CollinearJointsOfOneLinkUseTheRigidRule) {
  const Linkage linkage = test::example("chebyshev_lambda.json");
  const JointOrder order = order_joints(linkage);
  const Rule& last = order.rules.back();
  EXPECT_EQ(linkage.joints[last.k].name, "M");
  EXPECT_EQ(last.kind, RuleKind::kRigid);
}

TEST(JointOrder, UnderConstrainedJointsAreNamed) {
  Linkage linkage = test::complex_loop();
  linkage.links.erase(linkage.links.begin() + 3);  // drop H–P3: one degree of freedom too many
  try {
    order_joints(linkage);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.message(), "joints \"P1\", \"P2\", \"P3\" are not determined by the links (the linkage is under-constrained)");
    EXPECT_EQ(error.location(), "joints[4]");
  }
}

}  // namespace
}  // namespace reconfig::linkage
