#include <lvfusion/common/ProcessMemory.h>

#include <cstdlib>  // defines __GLIBC__ where it is glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace lvf::common
{
void retainLargeAllocations()
{
#if defined(__GLIBC__)
	// Blocks up to 64 MB from the heap, and free heap kept up to 256 MB.
	mallopt(M_MMAP_THRESHOLD, 64 << 20);
	mallopt(M_TRIM_THRESHOLD, 256 << 20);
#endif
}
}  // namespace lvf::common
