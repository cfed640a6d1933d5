#include "mlndt/cloud/cloud_format.h"

#include <gtest/gtest.h>

#include <string>

namespace mlndt {
namespace {

constexpr CloudFormat kAllFormats[] = {CloudFormat::PCD,
                                       CloudFormat::PLY,
                                       CloudFormat::KITTI_BIN,
                                       CloudFormat::UOS_3D,
                                       CloudFormat::XYZ};

TEST(CloudFormat, StringRoundTrip) {
  for (CloudFormat format : kAllFormats) {
    CloudFormat parsed =
        CloudFormat::XYZ == format ? CloudFormat::PCD : CloudFormat::XYZ;
    EXPECT_TRUE(StringToCloudFormat(CloudFormatToString(format), &parsed));
    EXPECT_EQ(parsed, format) << CloudFormatToString(format);
  }
}

TEST(CloudFormat, NamesAreUpperCase) {
  EXPECT_STREQ(CloudFormatToString(CloudFormat::PCD), "PCD");
  EXPECT_STREQ(CloudFormatToString(CloudFormat::PLY), "PLY");
  EXPECT_STREQ(CloudFormatToString(CloudFormat::KITTI_BIN), "KITTI_BIN");
  EXPECT_STREQ(CloudFormatToString(CloudFormat::UOS_3D), "UOS_3D");
  EXPECT_STREQ(CloudFormatToString(CloudFormat::XYZ), "XYZ");
}

TEST(CloudFormat, ParsesLowerCase) {
  CloudFormat format = CloudFormat::PCD;
  EXPECT_TRUE(StringToCloudFormat("kitti_bin", &format));
  EXPECT_EQ(format, CloudFormat::KITTI_BIN);
  EXPECT_TRUE(StringToCloudFormat("Uos_3d", &format));
  EXPECT_EQ(format, CloudFormat::UOS_3D);
}

TEST(CloudFormat, UnknownNameLeavesValueUnchanged) {
  CloudFormat format = CloudFormat::PLY;
  EXPECT_FALSE(StringToCloudFormat("las", &format));
  EXPECT_FALSE(StringToCloudFormat("", &format));
  EXPECT_EQ(format, CloudFormat::PLY);
}

TEST(CloudFormat, FromPathByExtension) {
  struct Case {
    const char* path;
    CloudFormat format;
  };
  const Case cases[] = {
      {"a.pcd", CloudFormat::PCD},
      {"/data/scans/000000.pcd", CloudFormat::PCD},
      {"target.ply", CloudFormat::PLY},
      {"velodyne/000000.bin", CloudFormat::KITTI_BIN},
      {"dat/scan000.3d", CloudFormat::UOS_3D},
      {"points.xyz", CloudFormat::XYZ},
      {"points.txt", CloudFormat::XYZ},
  };
  for (const Case& c : cases) {
    CloudFormat format = CloudFormat::PCD;
    std::string error;
    EXPECT_TRUE(CloudFormatFromPath(c.path, &format, &error))
        << c.path << ": " << error;
    EXPECT_EQ(format, c.format) << c.path;
  }
}

TEST(CloudFormat, FromPathIsCaseInsensitive) {
  CloudFormat format = CloudFormat::PCD;
  std::string error;
  EXPECT_TRUE(CloudFormatFromPath("SCAN.PLY", &format, &error));
  EXPECT_EQ(format, CloudFormat::PLY);
  EXPECT_TRUE(CloudFormatFromPath("scan000.3D", &format, &error));
  EXPECT_EQ(format, CloudFormat::UOS_3D);
  EXPECT_TRUE(CloudFormatFromPath("Cloud.Txt", &format, &error));
  EXPECT_EQ(format, CloudFormat::XYZ);
}

TEST(CloudFormat, FromPathUsesOnlyTheLastExtension) {
  CloudFormat format = CloudFormat::PCD;
  std::string error;
  EXPECT_TRUE(CloudFormatFromPath("run.2024.01/scan.pcd.ply", &format, &error));
  EXPECT_EQ(format, CloudFormat::PLY);
}

TEST(CloudFormat, UnknownExtensionNamesFileAndKnownExtensions) {
  CloudFormat format = CloudFormat::PLY;
  std::string error;
  EXPECT_FALSE(CloudFormatFromPath("/data/cloud.las", &format, &error));
  EXPECT_EQ(format, CloudFormat::PLY);
  EXPECT_NE(error.find("/data/cloud.las"), std::string::npos) << error;
  EXPECT_NE(error.find("'.las'"), std::string::npos) << error;
  for (const char* known : {".pcd", ".ply", ".bin", ".3d", ".xyz", ".txt"}) {
    EXPECT_NE(error.find(known), std::string::npos)
        << known << " missing from: " << error;
  }
}

TEST(CloudFormat, NoExtensionIsAnError) {
  CloudFormat format = CloudFormat::PCD;
  std::string error;
  EXPECT_FALSE(CloudFormatFromPath("/data/cloud", &format, &error));
  EXPECT_NE(error.find("/data/cloud"), std::string::npos) << error;
  EXPECT_NE(error.find("no file extension"), std::string::npos) << error;
}

}  // namespace
}  // namespace mlndt
