// The result tables (mlndt/common/result_table.h): every field of
// RegistrationSummaryTable() and the tables nested in it gives a value of
// its declared type, names are unique in each table, and each getter reads
// its own member (a summary with a distinct value in every field reads back
// field by field).

#include "mlndt/common/result_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>

#include "mlndt/registration/registration_summary.h"

namespace mlndt {
namespace {

// A summary whose fields hold distinct values (none the default).
RegistrationSummary DistinctSummary() {
  RegistrationSummary s;
  s.termination_type = TerminationType::DEGENERATE;
  s.message = "m";
  s.algorithm = "NDT";
  s.initial_reference_from_input_xi = Vector6d::Constant(0.5);
  s.reference_from_input_xi = Vector6d::Constant(0.25);
  s.reference_from_input.translation() = Vector3d(1.0, 2.0, 3.0);
  s.trace.resize(2);
  s.trace[1].iteration = 2;
  s.trace[1].time_s = 0.75;
  s.iterations_per_layer = {3, 4};
  s.num_iterations = 11;
  s.attempts = 12;
  s.point_iterations = 13;
  s.start_layer = 14;
  s.num_layers = 15;
  s.input_points = 16;
  s.range_filtered_points = 17;
  s.sampled_points = 18;
  s.matched_points = 19;
  s.unmatched_points = 20;
  s.map_occupied_cells = 21;
  s.map_bytes = 22;
  s.finest_cell_size_m = 1.5;
  s.map_time_s = 2.5;
  s.sampling_time_s = 3.5;
  s.solve_time_s = 4.5;
  s.total_time_s = 5.5;
  s.initial_score = 6.5;
  s.final_score = 7.5;
  s.quality.points = 23;
  s.quality.median_distance = 8.5;
  s.constraints.flatness = 9.5;
  s.constraints.flat_directions = 24;
  s.constraints.degenerate_directions.assign(2, Vector6d::Constant(0.125));
  s.hessian = Matrix6d::Constant(10.5);
  s.covariance = Matrix6d::Constant(11.5);
  return s;
}

void ExpectTypesMatch(const ResultTable& table, const void* object) {
  std::set<std::string> names;
  for (const ResultField& field : table.fields()) {
    EXPECT_TRUE(names.insert(field.name).second)
        << table.struct_name() << "." << field.name << " twice";
    const ResultValue value = field.get(object);
    EXPECT_EQ(value.index(), static_cast<size_t>(field.type))
        << table.struct_name() << "." << field.name;
    const bool nests = field.type == ResultType::STRUCT ||
                       field.type == ResultType::STRUCT_LIST;
    EXPECT_EQ(field.nested != nullptr, nests) << field.name;
    EXPECT_FALSE(field.help.empty()) << field.name;
    if (const auto* n = std::get_if<NestedResult>(&value)) {
      EXPECT_EQ(n->table, field.nested);
      ExpectTypesMatch(*n->table, n->object);
    }
    if (const auto* list = std::get_if<NestedResults>(&value)) {
      for (const void* o : list->objects) ExpectTypesMatch(*list->table, o);
    }
  }
}

TEST(ResultTable, EveryFieldGivesItsDeclaredType) {
  const RegistrationSummary summary = DistinctSummary();
  ExpectTypesMatch(RegistrationSummaryTable(), &summary);
  EXPECT_EQ(RegistrationSummaryTable().struct_name(), "RegistrationSummary");
}

TEST(ResultTable, EachGetterReadsItsOwnMember) {
  const RegistrationSummary s = DistinctSummary();
  const ResultTable& table = RegistrationSummaryTable();
  const std::map<std::string, int64_t> integers = {
      {"num_iterations", 11},
      {"attempts", 12},
      {"point_iterations", 13},
      {"start_layer", 14},
      {"num_layers", 15},
      {"input_points", 16},
      {"range_filtered_points", 17},
      {"sampled_points", 18},
      {"matched_points", 19},
      {"unmatched_points", 20},
      {"map_occupied_cells", 21},
      {"map_bytes", 22}};
  for (const auto& [name, expected] : integers) {
    ASSERT_NE(table.Find(name), nullptr) << name;
    EXPECT_EQ(std::get<int64_t>(table.Find(name)->Get(s)), expected) << name;
  }
  const std::map<std::string, double> numbers = {{"finest_cell_size_m", 1.5},
                                                 {"map_time_s", 2.5},
                                                 {"sampling_time_s", 3.5},
                                                 {"solve_time_s", 4.5},
                                                 {"total_time_s", 5.5},
                                                 {"initial_score", 6.5},
                                                 {"final_score", 7.5}};
  for (const auto& [name, expected] : numbers) {
    ASSERT_NE(table.Find(name), nullptr) << name;
    EXPECT_EQ(std::get<double>(table.Find(name)->Get(s)), expected) << name;
  }
  EXPECT_EQ(std::get<EnumName>(table.Find("termination_type")->Get(s)).name,
            "DEGENERATE");
  EXPECT_EQ(std::get<bool>(table.Find("usable")->Get(s)), false);
  EXPECT_EQ(std::get<std::string>(table.Find("algorithm")->Get(s)), "NDT");
  EXPECT_EQ(std::get<std::vector<int64_t>>(
                table.Find("iterations_per_layer")->Get(s)),
            (std::vector<int64_t>{3, 4}));
  EXPECT_EQ(std::get<Eigen::VectorXd>(
                table.Find("initial_reference_from_input_xi")->Get(s))(0),
            0.5);
  EXPECT_EQ(std::get<Eigen::MatrixXd>(table.Find("hessian")->Get(s))(0, 0),
            10.5);
  EXPECT_EQ(std::get<Eigen::MatrixXd>(table.Find("covariance")->Get(s))(5, 5),
            11.5);
  const auto pose =
      std::get<Eigen::MatrixXd>(table.Find("reference_from_input")->Get(s));
  ASSERT_EQ(pose.rows(), 4);
  EXPECT_EQ(pose(2, 3), 3.0);
}

TEST(ResultTable, NestedResultsReadTheirStructs) {
  const RegistrationSummary s = DistinctSummary();
  const ResultTable& table = RegistrationSummaryTable();
  const auto quality = std::get<NestedResult>(table.Find("quality")->Get(s));
  EXPECT_EQ(
      std::get<int64_t>(quality.table->Find("points")->get(quality.object)),
      23);
  EXPECT_EQ(std::get<double>(
                quality.table->Find("median_distance")->get(quality.object)),
            8.5);
  const auto constraints =
      std::get<NestedResult>(table.Find("constraints")->Get(s));
  const ResultTable& c = *constraints.table;
  EXPECT_EQ(std::get<double>(c.Find("flatness")->get(constraints.object)), 9.5);
  EXPECT_EQ(
      std::get<int64_t>(c.Find("flat_directions")->get(constraints.object)),
      24);
  const auto rows = std::get<Eigen::MatrixXd>(
      c.Find("degenerate_directions")->get(constraints.object));
  EXPECT_EQ(rows.rows(), 2);
  EXPECT_EQ(rows.cols(), 6);
  EXPECT_EQ(rows(1, 5), 0.125);
  const auto trace = std::get<NestedResults>(table.Find("trace")->Get(s));
  ASSERT_EQ(trace.objects.size(), 2u);
  EXPECT_EQ(
      std::get<int64_t>(trace.table->Find("iteration")->get(trace.objects[1])),
      2);
  EXPECT_EQ(
      std::get<double>(trace.table->Find("time_s")->get(trace.objects[1])),
      0.75);
}

}  // namespace
}  // namespace mlndt
