// Writes the seed corpus of the fuzz targets (tests/fuzz/corpus/<target>/):
// small valid files cut from the bundled data (data/kitti, data/koide3,
// data/room), hand-made files for the layouts the bundled data lacks, and
// broken files. The committed corpus was written by this program:
//
//   build-fuzz/tests/fuzz/mlndt_fuzz_corpus data tests/fuzz/corpus
//
// (.ci/fuzz builds it; it is not part of the fuzz run.)

#include <lzf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "mlndt/cloud/internal/cloud_readers.h"
#include "mlndt/cloud/io.h"
#include "mlndt/cloud/point_cloud.h"
#include "mlndt/grid/grid_io.h"

namespace mlndt {
namespace {

std::string out_dir;

void Write(const std::string& target,
           const std::string& name,
           const std::string& bytes) {
  const std::string folder = out_dir + "/" + target;
  std::filesystem::create_directories(folder);
  std::ofstream out(folder + "/" + name, std::ios::binary);
  out << bytes;
  out.close();
  if (!out) {
    std::cerr << "cannot write " << folder << "/" << name << "\n";
    std::exit(1);
  }
}

std::string ReadAll(const std::string& path) {
  std::string bytes, error;
  if (!internal::ReadFileToString(path, &bytes, &error)) {
    std::cerr << error << "\n";
    std::exit(1);
  }
  return bytes;
}

// The raw records after the header of a binary PCD.
std::string PcdBody(const std::string& bytes) {
  const size_t data = bytes.find("DATA binary\n");
  if (data == std::string::npos) {
    std::cerr << "not a binary PCD\n";
    std::exit(1);
  }
  return bytes.substr(data + std::strlen("DATA binary\n"));
}

std::string Header(const std::string& fields,
                   const std::string& sizes,
                   const std::string& types,
                   const std::string& counts,
                   size_t width,
                   size_t height,
                   const std::string& data) {
  return "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS " +
         fields + "\nSIZE " + sizes + "\nTYPE " + types + "\nCOUNT " + counts +
         "\nWIDTH " + std::to_string(width) + "\nHEIGHT " +
         std::to_string(height) + "\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " +
         std::to_string(width * height) + "\nDATA " + data + "\n";
}

template <typename T>
void Append(T value, std::string* out, bool big_endian = false) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (big_endian) std::reverse(bytes, bytes + sizeof(T));
  out->append(bytes, sizeof(T));
}

std::string Num(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.9g", value);
  return text;
}

std::string Lzf(const std::string& raw) {
  std::vector<char> packed(raw.size() + raw.size() / 16 + 64);
  const unsigned int n = lzf_compress(raw.data(),
                                      static_cast<unsigned int>(raw.size()),
                                      packed.data(),
                                      static_cast<unsigned int>(packed.size()));
  if (n == 0) {
    std::cerr << "lzf_compress failed\n";
    std::exit(1);
  }
  std::string out;
  Append(static_cast<uint32_t>(n), &out);
  Append(static_cast<uint32_t>(raw.size()), &out);
  out.append(packed.data(), n);
  return out;
}

std::string MapBody(const LayeredGrid& grid) {
  const std::string path =
      std::filesystem::temp_directory_path() / "mlndt_corpus.mlndtmap";
  std::string error;
  if (!SaveLayeredGrid(path, grid, &error)) {
    std::cerr << error << "\n";
    std::exit(1);
  }
  const std::string bytes = ReadAll(path);
  std::filesystem::remove(path);
  return bytes.substr(0, bytes.size() - 8);  // fuzz_map adds the checksum.
}

int Run(const std::string& data_dir) {
  // Slices of the bundled scans.
  const std::string kitti_raw = ReadAll(data_dir + "/kitti/pcd/000000.pcd");
  const std::string kitti_records = PcdBody(kitti_raw).substr(0, 40 * 12);
  const std::string koide_raw = ReadAll(data_dir + "/koide3/251370668.pcd");
  const std::string koide_records = PcdBody(koide_raw).substr(0, 40 * 16);
  std::vector<Eigen::Vector3d> kitti, room;
  std::string error;
  for (size_t i = 0; i < 40; ++i) {
    kitti.emplace_back(
        internal::LoadFloat(kitti_records.data() + 12 * i, 4, false),
        internal::LoadFloat(kitti_records.data() + 12 * i + 4, 4, false),
        internal::LoadFloat(kitti_records.data() + 12 * i + 8, 4, false));
  }
  std::vector<float> koide_intensity;
  for (size_t i = 0; i < 40; ++i) {
    koide_intensity.push_back(static_cast<float>(
        internal::LoadFloat(koide_records.data() + 16 * i + 12, 4, false)));
  }
  {
    std::vector<Eigen::Vector3d> all;
    if (!internal::ParsePcd(
            ReadAll(data_dir + "/room/room_scan1.pcd"), &all, &error)) {
      std::cerr << error << "\n";
      return 1;
    }
    room.assign(all.begin(), all.begin() + 40);
  }

  // ---- PCD ascii.
  {
    std::string text =
        Header("x y z", "4 4 4", "F F F", "1 1 1", 40, 1, "ascii");
    for (const Eigen::Vector3d& p : kitti)
      text += Num(p.x()) + " " + Num(p.y()) + " " + Num(p.z()) + "\n";
    Write("pcd_ascii", "kitti_000000_first40.pcd", text);
    std::string koide = Header(
        "x y z intensity", "4 4 4 4", "F F F F", "1 1 1 1", 20, 1, "ascii");
    for (size_t i = 0; i < 20; ++i) {
      for (int a = 0; a < 3; ++a) {
        koide += Num(internal::LoadFloat(
                     koide_records.data() + 16 * i + 4 * a, 4, false)) +
                 " ";
      }
      koide += Num(koide_intensity[i]) + "\n";
    }
    Write("pcd_ascii", "koide3_first20_intensity.pcd", koide);
    Write("pcd_ascii",
          "v06_padding_nan_crlf.pcd",
          "# .PCD v.6\r\nFIELDS x y _ z rgb\r\nSIZE 4 4 1 8 4\r\n"
          "TYPE F F U F U\r\nCOUNT 1 1 3 1 1\r\nWIDTH 3\r\nHEIGHT 1\r\n"
          "POINTS 3\r\nDATA ascii\r\n1 2 0 0 0 3 255\r\nnan nan 0 0 0 nan 0\r\n"
          "-1.5e2 +4 1 2 3 1e-3 7\r\n");
    Write("pcd_ascii",
          "organised_2x2_comments.pcd",
          "# comment\nVERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n"
          "COUNT 1 1 1\nWIDTH 2\nHEIGHT 2\n# another\nVIEWPOINT 0 0 0 1 0 0 "
          "0\nPOINTS 4\nDATA ascii\n0 0 0\n1 0 0\n\n0 1 0\n0 0 1\n");
    Write("pcd_ascii",
          "broken_points_mismatch.pcd",
          Header("x y z", "4 4 4", "F F F", "1 1 1", 3, 1, "ascii") +
              "1 2 3\n4 5 6\n");
    Write("pcd_ascii",
          "broken_bad_value.pcd",
          Header("x y z", "4 4 4", "F F F", "1 1 1", 2, 1, "ascii") +
              "1 2 3\n4 y 6\n");
    Write("pcd_ascii",
          "zero_points.pcd",
          Header("x y z", "4 4 4", "F F F", "1 1 1", 0, 1, "ascii"));
  }

  // ---- PCD binary.
  {
    Write("pcd_binary",
          "kitti_000000_first40.pcd",
          Header("x y z", "4 4 4", "F F F", "1 1 1", 40, 1, "binary") +
              kitti_records);
    Write("pcd_binary",
          "koide3_first40_intensity.pcd",
          Header("x y z intensity",
                 "4 4 4 4",
                 "F F F F",
                 "1 1 1 1",
                 40,
                 1,
                 "binary") +
              koide_records);
    std::string mixed = Header("normal x rgb y z _",
                               "4 8 4 8 8 1",
                               "F F U F F U",
                               "3 1 1 1 1 4",
                               4,
                               1,
                               "binary");
    for (size_t i = 0; i < 4; ++i) {
      for (int k = 0; k < 3; ++k) Append(0.5f * k, &mixed);
      Append(room[i].x(), &mixed);
      Append(static_cast<uint32_t>(0xff00ff), &mixed);
      Append(room[i].y(), &mixed);
      Append(room[i].z(), &mixed);
      mixed.append(4, '\0');
    }
    Write("pcd_binary", "room_double_extra_fields.pcd", mixed);
    std::string organised =
        Header("x y z", "4 4 4", "F F F", "1 1 1", 3, 2, "binary");
    for (size_t i = 0; i < 6; ++i) {
      for (int a = 0; a < 3; ++a) {
        Append(i == 2 ? std::nanf("") : static_cast<float>(kitti[i](a)),
               &organised);
      }
    }
    Write("pcd_binary", "organised_3x2_nan.pcd", organised);
    Write("pcd_binary",
          "broken_truncated.pcd",
          Header("x y z", "4 4 4", "F F F", "1 1 1", 40, 1, "binary") +
              kitti_records.substr(0, 40 * 12 - 5));
  }

  // ---- PCD binary_compressed (field-major, LZF).
  {
    std::string raw;
    for (int a = 0; a < 3; ++a) {
      for (const Eigen::Vector3d& p : room)
        Append(static_cast<float>(p(a)), &raw);
    }
    Write(
        "pcd_binary_compressed",
        "room_scan1_first40.pcd",
        Header("x y z", "4 4 4", "F F F", "1 1 1", 40, 1, "binary_compressed") +
            Lzf(raw));
    std::string raw4;
    for (int a = 0; a < 4; ++a) {
      for (size_t i = 0; i < 30; ++i) {
        Append(a < 3 ? static_cast<float>(internal::LoadFloat(
                           koide_records.data() + 16 * i + 4 * a, 4, false))
                     : koide_intensity[i],
               &raw4);
      }
    }
    Write("pcd_binary_compressed",
          "koide3_first30_intensity.pcd",
          Header("x y z intensity",
                 "4 4 4 4",
                 "F F F F",
                 "1 1 1 1",
                 30,
                 1,
                 "binary_compressed") +
              Lzf(raw4));
    std::string bad = Lzf(raw);
    bad[0] = static_cast<char>(0xff);  // Compressed size beyond the file.
    Write(
        "pcd_binary_compressed",
        "broken_compressed_size.pcd",
        Header("x y z", "4 4 4", "F F F", "1 1 1", 40, 1, "binary_compressed") +
            bad);
    std::string garbled = Lzf(raw);
    for (size_t i = 12; i < garbled.size(); i += 7) garbled[i] ^= 0x5a;
    Write(
        "pcd_binary_compressed",
        "broken_lzf_stream.pcd",
        Header("x y z", "4 4 4", "F F F", "1 1 1", 40, 1, "binary_compressed") +
            garbled);
  }

  // ---- PLY ascii.
  {
    std::string ply =
        "ply\nformat ascii 1.0\ncomment KITTI 000000, 30 points\n"
        "element vertex 30\nproperty float x\nproperty float y\n"
        "property float z\nend_header\n";
    for (size_t i = 0; i < 30; ++i)
      ply += Num(kitti[i].x()) + " " + Num(kitti[i].y()) + " " +
             Num(kitti[i].z()) + "\n";
    Write("ply_ascii", "kitti_000000_first30.ply", ply);
    Write("ply_ascii",
          "faces_extra_properties.ply",
          "ply\nformat ascii 1.0\nobj_info made by hand\nelement vertex 3\n"
          "property double x\nproperty uchar red\nproperty float64 y\n"
          "property float32 z\nelement face 1\nproperty list uchar int "
          "vertex_indices\nend_header\n0 255 0 0\n1 0 0 0\n0 1 1 0.5\n"
          "3 0 1 2\n");
    Write("ply_ascii",
          "elements_before_vertices.ply",
          "ply\nformat ascii 1.0\nelement camera 1\nproperty float fx\n"
          "element vertex 2\nproperty float x\nproperty float y\nproperty "
          "float z\nend_header\n500\n1 2 3\n4 5 6\n");
    Write("ply_ascii",
          "broken_truncated.ply",
          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
          "property float y\nproperty float z\nend_header\n1 2 3\n4 5 6\n");
  }

  // ---- PLY binary.
  {
    Write("ply_binary",
          "kitti_000000_first40_le.ply",
          internal::EncodePlyBinary(PointCloud(kitti)));
    std::string be =
        "ply\nformat binary_big_endian 1.0\nelement vertex 20\n"
        "property double x\nproperty double y\nproperty double z\n"
        "property uchar intensity\nend_header\n";
    for (size_t i = 0; i < 20; ++i) {
      for (int a = 0; a < 3; ++a) Append(room[i](a), &be, /*big_endian=*/true);
      be.push_back(static_cast<char>(i));
    }
    Write("ply_binary", "room_first20_be_double.ply", be);
    std::string faces =
        "ply\nformat binary_little_endian 1.0\nelement face 2\n"
        "property list uchar int vertex_indices\nproperty short flags\n"
        "element vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nend_header\n";
    for (int f = 0; f < 2; ++f) {
      faces.push_back(3);
      for (int k = 0; k < 3; ++k) Append(static_cast<int32_t>(k), &faces);
      Append(static_cast<int16_t>(f), &faces);
    }
    for (size_t i = 0; i < 3; ++i) {
      for (int a = 0; a < 3; ++a)
        Append(static_cast<float>(kitti[i](a)), &faces);
    }
    Write("ply_binary", "faces_before_vertices_le.ply", faces);
    const std::string le = internal::EncodePlyBinary(PointCloud(kitti));
    Write("ply_binary", "broken_truncated_le.ply", le.substr(0, le.size() - 7));
  }

  // ---- KITTI .bin.
  {
    std::string bin;
    for (const Eigen::Vector3d& p : kitti) {
      for (int a = 0; a < 3; ++a) Append(static_cast<float>(p(a)), &bin);
      Append(0.25f, &bin);
    }
    Write("kitti_bin", "kitti_000000_first40.bin", bin);
    Write("kitti_bin", "koide3_first40.bin", koide_records);
    Write("kitti_bin", "broken_20_bytes.bin", bin.substr(0, 20));
  }

  // ---- 3DTK .3d (cm, left-handed: x_l = -y_r, y_l = z_r, z_l = x_r).
  {
    std::string uos = "40 x 1\n";
    for (const Eigen::Vector3d& p : kitti) {
      uos += Num(-100 * p.y()) + " " + Num(100 * p.z()) + " " +
             Num(100 * p.x()) + " 0.5\n";
    }
    Write("uos_3d", "kitti_000000_first40.3d", uos);
    Write("uos_3d", "blank_lines.3d", "\n100 0 0\n\n  -5.5\t20 1e3  \n");
    Write("uos_3d", "broken_line.3d", "1 2 3\n4 five 6\n");
  }

  // ---- xyz text.
  {
    std::string xyz = "# x y z from KITTI 000000\n";
    for (const Eigen::Vector3d& p : kitti)
      xyz += Num(p.x()) + " " + Num(p.y()) + " " + Num(p.z()) + "\n";
    Write("xyz", "kitti_000000_first40.xyz", xyz);
    Write("xyz",
          "commas_extra_columns.xyz",
          "1,2,3\n4 5 6 0.9 x\r\n 7.5\t8 , 9\nnan,1,2\n");
    Write("xyz", "broken_two_numbers.xyz", "1 2 3\n4 5\n");
  }

  // ---- Pose files.
  Write("kitti_poses",
        "poses_velo.txt",
        ReadAll(data_dir + "/kitti/poses_velo.txt"));
  Write("kitti_poses",
        "poses_cam0.txt",
        ReadAll(data_dir + "/kitti/poses_cam0.txt"));
  Write("kitti_poses", "broken_11_numbers.txt", "1 0 0 0 0 1 0 0 0 0 1\n");
  Write("kitti_poses", "broken_reflection.txt", "-1 0 0 0 0 1 0 0 0 0 1 0\n");
  Write("kitti_calib", "calib.txt", ReadAll(data_dir + "/kitti/calib.txt"));
  Write("kitti_calib", "broken_no_tr.txt", "P0: 1 0 0 0 0 1 0 0 0 0 1 0\n");
  Write("kitti_calib", "broken_tr_11.txt", "Tr: 1 0 0 0 0 1 0 0 0 0 1\n");
  Write("3dtk_pose", "origin.pose", "0 0 0\n0 0 0\n");
  Write("3dtk_pose", "moving.pose", "12.5 -3 400.25\n1.5 -90 30\n");
  Write("3dtk_pose", "broken_5_numbers.pose", "1 2 3\n4 5\n");

  // ---- Map files (bodies without the checksum).
  {
    std::mt19937 rng(3);
    std::normal_distribution<double> n(0.0, 0.4);
    PointCloud clusters;
    const double centres[3][3] = {{0, 0, 0}, {6, 1, 0.5}, {2, 5, -1}};
    for (const auto& c : centres) {
      for (int i = 0; i < 12; ++i) {
        clusters.Add(
            Eigen::Vector3d(c[0] + n(rng), c[1] + n(rng), c[2] + 0.5 * n(rng)));
      }
    }
    LayeredGridOptions options;
    options.num_layers = 2;
    LayeredGrid grid;
    if (!LayeredGrid::Build(options, clusters, &grid, &error)) {
      std::cerr << error << "\n";
      return 1;
    }
    Write("map", "three_clusters_2_layers.body", MapBody(grid));
    options.num_layers = 1;
    LayeredGrid::Build(options, clusters, &grid, &error);
    Write("map", "three_clusters_1_layer.body", MapBody(grid));

    PointCloud scan;
    if (!ReadPointCloud(
            data_dir + "/kitti/pcd/000000.pcd", &scan, nullptr, &error)) {
      std::cerr << error << "\n";
      return 1;
    }
    PointCloud near;
    for (const Eigen::Vector3d& p : scan.points()) {
      if (p.head<2>().norm() < 12.0 && near.size() < 4000) near.Add(p);
    }
    options.num_layers = 3;
    if (!LayeredGrid::Build(options, near, &grid, &error)) {
      std::cerr << error << "\n";
      return 1;
    }
    Write("map", "kitti_000000_near_3_layers.body", MapBody(grid));
    std::string broken = MapBody(grid).substr(0, 96);
    broken[16] = 17;  // 17 layers.
    Write("map", "broken_17_layers.body", broken);
  }
  return 0;
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: " << argv[0] << " DATA_DIR OUT_DIR\n";
    return 1;
  }
  mlndt::out_dir = argv[2];
  return mlndt::Run(argv[1]);
}
