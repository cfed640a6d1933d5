#include "lab/io/point_cloud2.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace mlndt {
namespace {

// A message with `fields` and `rows` x `cols` points of `point_step` bytes
// and `row_padding` spare bytes at the end of each row, zero-filled.
struct Message {
  PointCloud2View view;
  std::vector<uint8_t> data;

  Message(std::vector<PointCloud2Field> fields,
          uint32_t rows,
          uint32_t cols,
          uint32_t point_step,
          uint32_t row_padding) {
    view.stamp_s = 1700000000.5;
    view.frame_id = "lidar";
    view.height = rows;
    view.width = cols;
    view.fields = std::move(fields);
    view.point_step = point_step;
    view.row_step = cols * point_step + row_padding;
    data.assign(size_t{view.row_step} * rows, 0);
    Rebind();
  }
  void Rebind() {
    view.data = data.data();
    view.data_size = data.size();
  }
  template <typename T>
  void Put(uint32_t row, uint32_t col, uint32_t offset, T value) {
    std::memcpy(data.data() + size_t{row} * view.row_step +
                    size_t{col} * view.point_step + offset,
                &value,
                sizeof(T));
  }
};

// float64 x/y/z and Ouster's uint32 "t" [ns], 2 rows of 3 points with row
// padding: every point in row order, times in seconds, the NaN point
// dropped with its time.
TEST(DecodePointCloud2, RowsPaddingFloat64AndNanosecondTimes) {
  Message m({{"x", 0, kPointFieldFloat64},
             {"y", 8, kPointFieldFloat64},
             {"z", 16, kPointFieldFloat64},
             {"t", 24, kPointFieldUint32}},
            2,
            3,
            32,
            5);
  for (uint32_t r = 0; r < 2; ++r) {
    for (uint32_t c = 0; c < 3; ++c) {
      const double k = 3.0 * r + c;
      m.Put(r, c, 0, k + 0.25);
      m.Put(r, c, 8, -k);
      m.Put(r, c, 16, 2.0 * k);
      m.Put(r, c, 24, static_cast<uint32_t>(1000 * (3 * r + c)));
    }
  }
  m.Put(1, 1, 8, std::numeric_limits<double>::quiet_NaN());  // Point 4.
  PointCloud2Scan scan;
  std::string error;
  ASSERT_TRUE(DecodePointCloud2(m.view, &scan, &error)) << error;
  EXPECT_EQ(scan.stamp_s, 1700000000.5);
  EXPECT_EQ(scan.frame_id, "lidar");
  EXPECT_EQ(scan.time_field, "t");
  const std::vector<int> kept = {0, 1, 2, 3, 5};
  ASSERT_EQ(scan.cloud.size(), kept.size());
  ASSERT_EQ(scan.point_times_s.size(), kept.size());
  for (size_t i = 0; i < kept.size(); ++i) {
    const double k = kept[i];
    EXPECT_EQ(scan.cloud[i], Eigen::Vector3d(k + 0.25, -k, 2.0 * k)) << i;
    EXPECT_EQ(scan.point_times_s[i], 1000.0 * k * 1e-9) << i;
  }
}

// Hesai's absolute float64 "timestamp" becomes relative to the stamp;
// float32 x/y/z are read as floats.
TEST(DecodePointCloud2, AbsoluteTimestampsBecomeRelative) {
  Message m({{"x", 0, kPointFieldFloat32},
             {"y", 4, kPointFieldFloat32},
             {"z", 8, kPointFieldFloat32},
             {"timestamp", 16, kPointFieldFloat64}},
            1,
            2,
            24,
            0);
  m.Put(0, 0, 0, 0.1f);
  m.Put(0, 1, 0, 0.2f);
  m.Put(0, 0, 16, m.view.stamp_s + 0.03125);
  m.Put(0, 1, 16, m.view.stamp_s - 0.0625);
  PointCloud2Scan scan;
  std::string error;
  ASSERT_TRUE(DecodePointCloud2(m.view, &scan, &error)) << error;
  ASSERT_EQ(scan.cloud.size(), 2u);
  EXPECT_EQ(scan.cloud[0].x(), static_cast<double>(0.1f));
  EXPECT_EQ(scan.time_field, "timestamp");
  EXPECT_EQ(scan.point_times_s, (std::vector<double>{0.03125, -0.0625}));
}

// No time field: no times; a message of only NaN points decodes to an
// empty cloud (the caller decides).
TEST(DecodePointCloud2, WithoutTimesAndWithoutFinitePoints) {
  Message m({{"x", 0, kPointFieldFloat32},
             {"y", 4, kPointFieldFloat32},
             {"z", 8, kPointFieldFloat32},
             {"intensity", 12, kPointFieldFloat32}},
            1,
            1,
            16,
            0);
  m.Put(0, 0, 0, std::numeric_limits<float>::quiet_NaN());
  PointCloud2Scan scan;
  std::string error;
  ASSERT_TRUE(DecodePointCloud2(m.view, &scan, &error)) << error;
  EXPECT_TRUE(scan.cloud.empty());
  EXPECT_TRUE(scan.point_times_s.empty());
  EXPECT_EQ(scan.time_field, "");
}

// Layouts it cannot read are refused with a reason and leave *scan as it
// was.
TEST(DecodePointCloud2, RefusesWhatItCannotReadAndLeavesTheScan) {
  const std::vector<PointCloud2Field> xyz = {{"x", 0, kPointFieldFloat32},
                                             {"y", 4, kPointFieldFloat32},
                                             {"z", 8, kPointFieldFloat32}};
  PointCloud2Scan scan;
  scan.frame_id = "untouched";
  std::string error;

  Message no_z({xyz[0], xyz[1]}, 1, 1, 12, 0);
  EXPECT_FALSE(DecodePointCloud2(no_z.view, &scan, &error));
  EXPECT_EQ(error, "no float32/float64 x, y and z fields");

  Message integer_z({xyz[0], xyz[1], {"z", 8, kPointFieldInt32}}, 1, 1, 12, 0);
  EXPECT_FALSE(DecodePointCloud2(integer_z.view, &scan, &error));

  Message big_endian(xyz, 1, 1, 12, 0);
  big_endian.view.is_bigendian = true;
  EXPECT_FALSE(DecodePointCloud2(big_endian.view, &scan, &error));
  EXPECT_NE(error.find("big-endian"), std::string::npos) << error;

  Message outside(xyz, 1, 1, 10, 0);  // z ends at byte 12 > point_step 10.
  EXPECT_FALSE(DecodePointCloud2(outside.view, &scan, &error));
  EXPECT_NE(error.find("outside point_step 10"), std::string::npos) << error;

  Message short_data(xyz, 2, 4, 12, 0);
  short_data.data.resize(short_data.data.size() - 1);
  short_data.Rebind();
  EXPECT_FALSE(DecodePointCloud2(short_data.view, &scan, &error));
  EXPECT_NE(error.find("fewer than height x row_step (2 x 48)"),
            std::string::npos)
      << error;

  Message short_rows(xyz, 1, 4, 12, 0);
  short_rows.view.row_step = 40;  // < width x point_step.
  EXPECT_FALSE(DecodePointCloud2(short_rows.view, &scan, &error));
  EXPECT_EQ(scan.frame_id, "untouched");
  // A huge width (a corrupt header) names width and point_step, not the
  // data's size.
  EXPECT_NE(error.find("row_step 40 is less than width x point_step (4 x 12 "
                       "= 48)"),
            std::string::npos)
      << error;
  Message huge_width(xyz, 1, 4, 12, 0);
  huge_width.view.width = 4000000000u;
  EXPECT_FALSE(DecodePointCloud2(huge_width.view, &scan, &error));
  EXPECT_NE(error.find("width x point_step (4000000000 x 12"),
            std::string::npos)
      << error;
}

}  // namespace
}  // namespace mlndt
