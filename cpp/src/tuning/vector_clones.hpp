// SERVOBENCH_VECTOR_CLONES before a hot loop's function: with GCC on x86-64 Linux it is compiled twice, for AVX2+FMA
// (Haswell and later) and for the baseline, and the loader picks the one the CPU runs (ifunc); elsewhere nothing.
// Used by the broadband excitations and their DFT at the lines (tuning/multisine.cpp, spectral_lines.cpp).
#pragma once

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define SERVOBENCH_VECTOR_CLONES __attribute__((target_clones("arch=haswell", "default")))
#else
#define SERVOBENCH_VECTOR_CLONES
#endif
