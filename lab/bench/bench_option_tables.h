#pragma once

// The descriptions (mlndt/common/option_table.h) of mlndt_bench's
// single-value options (bench.h and the structs it holds): the PCL peers'
// settings, the rounds and their success thresholds, the pairs per folder.
// Not in them: BenchGrid (lists that enumerate the grid of configurations,
// set by mlndt_bench's list flags; its seed is --seed, the shared
// registration flag's name), BenchPairsOptions' folder, sets, gaps, starts
// and offsets (a path and lists), BenchRoundsOptions::on_round (a
// callback). From them come PclBenchOptions::IsValid's ranges, mlndt_bench's
// flags and the option reference. Built into mlndt_lab (not
// mlndt_lab_bench) so that the option reference and the flag surface test
// see them without PCL.

#include "mlndt/common/option_table.h"

namespace mlndt {

const OptionTable& PclBenchOptionsTable();
const OptionTable& BenchThresholdsTable();
const OptionTable& BenchRoundsOptionsTable();
const OptionTable& BenchPairsOptionsTable();
// BenchOptions' own fields and the tables above nested.
const OptionTable& BenchOptionsTable();

}  // namespace mlndt
