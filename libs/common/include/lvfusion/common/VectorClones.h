#pragma once
// Functions marked LVF_VECTOR_CLONES are compiled twice, for AVX2 and for
// the baseline, and the loader picks the one the CPU runs. A feature test:
// "arch=..." clones test the CPU model and miss newer ones.
//
// Where the compiler cannot vectorise a loop by itself (gathers, the
// pair-word multiply-adds), a function written with AVX2 intrinsics is
// marked __attribute__((target("avx2"))) under LVF_HAVE_AVX2_INTRINSICS and
// called only where cpuHasAvx2(); the plain code stays beside it for other
// CPUs and compilers.

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define LVF_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define LVF_VECTOR_CLONES
#endif

#if defined(__x86_64__) && defined(__GNUC__)
#define LVF_HAVE_AVX2_INTRINSICS 1
namespace lvf::common
{
/** Whether the CPU this runs on has AVX2 (asked once). */
inline bool cpuHasAvx2()
{
	static const bool has = __builtin_cpu_supports("avx2");
	return has;
}
}  // namespace lvf::common
#endif
