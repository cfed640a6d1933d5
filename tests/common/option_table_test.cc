// The option tables (mlndt/common/option_table.h): every described field of
// RegistrationOptions and NdtOptions is rejected by the struct's IsValid
// just outside each end of its range, with a message naming the field; an
// enum field holding no value of its enum likewise; every field's default
// reads back as itself; no two entries describe the same member.

#include "mlndt/common/option_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "mlndt/ndt/ndt_registration.h"
#include "mlndt/registration/registration_options.h"

namespace mlndt {
namespace {

struct Leaf {
  std::string path;
  const OptionField* field;
};

void CollectLeaves(const OptionTable& table,
                   const std::string& prefix,
                   std::vector<Leaf>* leaves) {
  for (const OptionField& field : table.fields()) {
    if (field.type == OptionType::STRUCT) {
      CollectLeaves(*field.nested, prefix + field.name + ".", leaves);
    } else {
      leaves->push_back({prefix + field.name, &field});
    }
  }
}

// Values just outside the range: below lo and above hi (finite ends only).
std::vector<double> OutsideValues(const OptionField& field) {
  const OptionRange& r = field.range;
  const bool integer = field.type == OptionType::INT;
  std::vector<double> values;
  if (std::isfinite(r.lo)) {
    double v = r.lo_open ? r.lo
               : integer ? r.lo - 1
                         : std::nextafter(r.lo, -1e300);
    if (r.or_zero && v == 0.0) v = r.lo / 2;
    if (!(r.or_zero && v == 0.0)) values.push_back(v);
  }
  if (std::isfinite(r.hi)) {
    values.push_back(r.hi_open ? r.hi
                     : integer ? r.hi + 1
                               : std::nextafter(r.hi, 1e300));
  }
  return values;
}

void SetNumber(const OptionField& field, double value, void* owner) {
  if (field.type == OptionType::INT) {
    field.Ref<int>(owner) = static_cast<int>(value);
  } else if (field.type == OptionType::DOUBLE) {
    field.Ref<double>(owner) = value;
  } else {
    field.Ref<std::vector<double>>(owner) = {value};
  }
}

template <typename Options>
void ExpectBoundsRejected(const OptionTable& table) {
  std::vector<Leaf> leaves;
  CollectLeaves(table, "", &leaves);
  int checked = 0;
  for (const Leaf& leaf : leaves) {
    const OptionField& field = *leaf.field;
    std::vector<std::function<void(void*)>> breakers;
    if (field.type == OptionType::ENUM) {
      breakers.push_back(
          [&field](void* owner) { field.set_enum(field.locate(owner), 99); });
    } else if (field.has_range) {
      for (const double v : OutsideValues(field)) {
        breakers.push_back(
            [&field, v](void* owner) { SetNumber(field, v, owner); });
      }
    }
    for (const auto& do_break : breakers) {
      Options options;
      const void* owner = nullptr;
      ASSERT_NE(table.FindPath(leaf.path, &options, &owner), nullptr);
      do_break(const_cast<void*>(owner));
      std::string error;
      EXPECT_FALSE(options.IsValid(&error)) << leaf.path;
      EXPECT_NE(error.find(field.name), std::string::npos)
          << leaf.path << ": " << error;
      EXPECT_EQ(error.rfind("invalid option: ", 0), 0u) << error;
      ++checked;
    }
  }
  // Every range end and enum of the description was tried.
  EXPECT_GT(checked, static_cast<int>(leaves.size()));
}

TEST(OptionTable, RegistrationOptionsRejectsEveryOutOfRangeValue) {
  ExpectBoundsRejected<RegistrationOptions>(RegistrationOptionsTable());
}

TEST(OptionTable, NdtOptionsRejectsEveryOutOfRangeValue) {
  ExpectBoundsRejected<NdtOptions>(NdtOptionsTable());
}

TEST(OptionTable, DefaultsAreValidAndReadBackAsThemselves) {
  for (const OptionTable* table :
       {&RegistrationOptionsTable(), &NdtOptionsTable()}) {
    std::vector<Leaf> leaves;
    CollectLeaves(*table, "", &leaves);
    for (const Leaf& leaf : leaves) {
      const void* owner = nullptr;
      table->FindPath(leaf.path, table->defaults(), &owner);
      const std::string text = leaf.field->Format(owner);
      RegistrationOptions scratch_r;
      NdtOptions scratch_n;
      void* scratch = table == &NdtOptionsTable()
                          ? static_cast<void*>(&scratch_n)
                          : static_cast<void*>(&scratch_r);
      const void* target = nullptr;
      table->FindPath(leaf.path, scratch, &target);
      std::string error;
      ASSERT_TRUE(leaf.field->Parse(text, const_cast<void*>(target), &error))
          << leaf.path << " = " << text << ": " << error;
      EXPECT_EQ(leaf.field->Format(target), text) << leaf.path;
      std::string why;
      EXPECT_TRUE(leaf.field->CheckRange(owner, "", &why)) << why;
      EXPECT_FALSE(leaf.field->help.empty()) << leaf.path;
    }
  }
}

// Two entries of one table pointing at one member would make one of the
// fields unreachable (a copy-paste slip).
TEST(OptionTable, EveryEntryDescribesItsOwnMember) {
  RegistrationOptions options;
  std::vector<Leaf> leaves;
  CollectLeaves(RegistrationOptionsTable(), "", &leaves);
  std::set<const void*> addresses;
  for (const Leaf& leaf : leaves) {
    const void* owner = nullptr;
    RegistrationOptionsTable().FindPath(leaf.path, &options, &owner);
    EXPECT_TRUE(
        addresses.insert(leaf.field->locate(const_cast<void*>(owner))).second)
        << leaf.path;
  }
  EXPECT_GE(leaves.size(), 45u);
}

TEST(OptionTable, ParseRefusesTextOfTheWrongType) {
  RegistrationOptions options;
  const void* owner = nullptr;
  const OptionField* field =
      RegistrationOptionsTable().FindPath("objective.loss", &options, &owner);
  ASSERT_NE(field, nullptr);
  std::string error;
  EXPECT_FALSE(field->Parse("tukey", const_cast<void*>(owner), &error));
  EXPECT_EQ(error, "expected none, huber or cauchy");
  EXPECT_TRUE(field->Parse("Huber", const_cast<void*>(owner), &error));
  EXPECT_EQ(options.objective.loss, LossType::HUBER);
  field = RegistrationOptionsTable().FindPath("num_threads", &options, &owner);
  EXPECT_FALSE(field->Parse("2.5", const_cast<void*>(owner), &error));
  EXPECT_EQ(error, "expected an integer");
  EXPECT_EQ(RegistrationOptionsTable().FindPath("grid.no_such_field"), nullptr);
}

TEST(OptionRange, TextNamesTheInterval) {
  EXPECT_EQ(Closed(1e-3, 1e3).ToString(), "in [0.001, 1000]");
  EXPECT_EQ(LeftOpen(0, 1).ToString(), "in (0, 1]");
  EXPECT_EQ(RightOpen(0, 1).ToString(), "in [0, 1)");
  EXPECT_EQ(AtLeast(1).ToString(), ">= 1");
  EXPECT_EQ(ClosedOrZero(1e-3, 1e5).ToString(), "in [0.001, 100000] or 0");
  EXPECT_FALSE(Closed(0, 1).Contains(std::nan("")));
  EXPECT_TRUE(ClosedOrZero(1, 2).Contains(0.0));
  EXPECT_FALSE(ClosedOrZero(1, 2).Contains(0.5));
}

}  // namespace
}  // namespace mlndt
