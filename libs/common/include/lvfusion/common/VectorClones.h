#pragma once
// Functions marked LVF_VECTOR_CLONES are compiled twice, for AVX2 and for
// the baseline, and the loader picks the one the CPU runs. A feature test:
// "arch=..." clones test the CPU model and miss newer ones.

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define LVF_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define LVF_VECTOR_CLONES
#endif
