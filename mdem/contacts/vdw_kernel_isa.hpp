#pragma once
// The instruction set the anisotropic contact's table kernel runs on (vdw_contact.cpp). Its loop
// is compiled twice on x86-64 with GCC or Clang: for the baseline the project builds for (SSE2,
// no -march), and for AVX2, chosen at run time by the CPU. The AVX2 version executes the same
// IEEE operations in the same order in their three-operand VEX forms (no FMA), so the two give
// bit-identical results. The AVX2 loop needs a fifth fewer instructions, mostly register copies
// that current cores eliminate anyway, so it saves far less time (docs/benchmarks.md, issue 16).
namespace mesochain::mdem {

#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
#define MESOCHAIN_VDW_AVX2_CLONE 1
#else
#define MESOCHAIN_VDW_AVX2_CLONE 0
#endif

enum class VdwKernelIsa { Baseline, Avx2 };

// The version the table kernel calls now.
VdwKernelIsa vdwKernelIsa();
// true: the baseline version even on AVX2 CPUs (tests and benchmarks compare the two); false: by the CPU.
void forceBaselineVdwKernel(bool on);

}  // namespace mesochain::mdem
