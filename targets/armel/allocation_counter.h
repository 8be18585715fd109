#pragma once
// Counts every heap allocation of the program it is linked into:
// targets/armel/allocation_counter.cpp replaces the global operator new, so allocations hidden in
// the standard library count too. What targets/armel/frame_allocation_test.cpp uses to prove that a
// frame allocates nothing.

namespace octopoint {

// Allocations through any form of operator new (the array and nothrow forms of libstdc++ forward
// to the replaced ones) since the program started.
long heapAllocationCount();

}  // namespace octopoint
