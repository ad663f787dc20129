#include "reconfig/collision/detector_settings.h"

#include <gtest/gtest.h>

namespace reconfig::collision {
namespace {

TEST(DetectorSettings, UnsetSettingsKeepTheBaseAndSetOnesReplaceIt) {
  DetectorOptions base;
  base.tolerance = 4e-3;
  base.all_contacts = true;  // not a design's setting: always the base's
  const DetectorOptions kept = with_settings(base, {});
  EXPECT_EQ(settings_of(kept), settings_of(base));
  EXPECT_TRUE(kept.all_contacts);

  const DetectorOptions changed = with_settings(base, {.dop = 80, .frame = 0.05});
  EXPECT_EQ(changed.dop, DopFamily::k80);
  EXPECT_EQ(changed.frame, 0.05);
  EXPECT_EQ(changed.tolerance, 4e-3);
  EXPECT_EQ(changed.box_resolution, base.box_resolution);
  EXPECT_TRUE(changed.all_contacts);
}

TEST(DetectorSettings, EverySavedSettingComesBack) {
  DetectorOptions options;
  options.tolerance = 2.5e-4;
  options.dop = DopFamily::k8;
  options.box_resolution = 0;
  options.frame = 0.125;
  options.conservative = true;
  const scene::CollisionSettings saved = settings_of(options);
  EXPECT_TRUE(saved.problem().empty());
  EXPECT_EQ(saved.dop, 8);
  // Onto options that differ in every saved setting.
  const DetectorOptions restored = with_settings(DetectorOptions{}, saved);
  EXPECT_EQ(settings_of(restored), saved);
  EXPECT_EQ(restored.dop, DopFamily::k8);
  EXPECT_TRUE(restored.conservative);
}

}  // namespace
}  // namespace reconfig::collision
