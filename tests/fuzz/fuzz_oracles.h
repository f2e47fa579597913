// What every fuzz target asserts about the library's answer to an input: either a clear error, or
// refined tables and evaluations that satisfy invariants any correct refinement satisfies.
#pragma once

#include <exception>
#include <string>
#include <vector>

#include <quadtri/far/refiner.h>

namespace quadtri::fuzz {

// Memory budget of the Refiners under fuzzing: large enough for a few-KB mesh at level 3, small
// enough that a hostile mesh is refused long before libFuzzer's RSS limit.
constexpr std::size_t kFuzzBudgetBytes = std::size_t(64) << 20;

// Prints the violated invariant and aborts, so that libFuzzer keeps the input as a crash.
[[noreturn]] void fail(const std::string& what);

// An error is clear when it says something.
void expectMessage(const std::exception& error);

// Checks levels 1..maxLevel() of `refiner` (built from finite `control` positions, 3 floats per
// control vertex): every table well-formed and a partition of unity; the per-level and factorized
// evaluations equal bitwise between CpuEvaluator and TbbEvaluator, finite wherever their magnitude
// bound allows, equal to each other within rounding, and moved by t when the control moves by t.
void checkRefinement(const Refiner& refiner, const std::vector<float>& control);

}  // namespace quadtri::fuzz
