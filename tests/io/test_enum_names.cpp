// test_enum_names.cpp: one name table per enum (rodshape/enum_names.hpp), read both ways: every
// value has one name, to_string() says it, value_of() gives the value back, and the task reader
// takes the names of the table (rod.model).
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "rodshape/core/rod_properties.hpp"
#include "rodshape/io/task_reader.hpp"
#include "rodshape/sim/plan_validation.hpp"
#include "rodshape/sim/plant.hpp"
#include "rodshape/solvers/follow_equilibrium.hpp"
#include "rodshape/solvers/solve_status.hpp"

namespace rodshape {
namespace test_enum_names {
namespace {

template <typename Enum, std::size_t N>
void expect_one_name_per_value(const EnumNames<Enum, N>& table) {
  std::set<std::string_view> names;
  for (std::size_t i = 0; i < N; ++i) {
    const EnumName<Enum>& entry = table[i];
    EXPECT_EQ(static_cast<std::size_t>(entry.value), i)
        << entry.name << ": not in the enum's order";
    EXPECT_TRUE(names.insert(entry.name).second) << entry.name << " twice";
    EXPECT_EQ(to_string(entry.value), entry.name);
    EXPECT_EQ(value_of(table, entry.name), entry.value);
  }
  EXPECT_FALSE(value_of(table, "no_such_name"));
  EXPECT_EQ(names_of(table).size(), N);
}

TEST(EnumNames, EveryTableNamesEachValueOnceInOrder) {
  expect_one_name_per_value(kSolveStatusNames);
  expect_one_name_per_value(kFollowEventNames);
  expect_one_name_per_value(kConstitutiveModelNames);
  expect_one_name_per_value(kPlantEventKindNames);
  expect_one_name_per_value(kValidationStatusNames);
  // A value the table lacks (cast from an integer) has the table's fallback.
  EXPECT_EQ(to_string(static_cast<SolveStatus>(99)), "unknown");
}

TEST(EnumNames, TheTaskReaderTakesTheTablesNames) {
  for (const EnumName<ConstitutiveModel>& entry : kConstitutiveModelNames) {
    const std::string text = "rod:\n  length: 0.29\n  model: " + std::string(entry.name) +
                             "\n  stiffness: {EA: 1280, GA: 427, EIx: 0.04, EIy: 0.04, GJ: "
                             "0.028}\ntip:\n  wrench: {force: [0, 0, 0], moment: [0, 0, 0]}\n";
    EXPECT_EQ(parse_equilibrium_task(text, "task.yaml").rod.properties.model, entry.value);
  }
}

}  // namespace
}  // namespace test_enum_names
}  // namespace rodshape
