#pragma once
// Random numbers that are the same on every platform: the network generators draw from
// std::mt19937_64 (whose sequence the standard fixes) and convert with this function, not with
// std::uniform_real_distribution (whose algorithm is left to the library). Their sines, cosines
// and logarithms come from portable_math.hpp, not libm (test
// CliDem.QuarterFilmRegeneratesTheCommittedBenchFilm).
#include <random>

namespace mesochain::mdem {

// Uniform double in [0, 1) from the top 53 random bits.
inline double uniformUnit(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1.0p-53; }

}  // namespace mesochain::mdem
