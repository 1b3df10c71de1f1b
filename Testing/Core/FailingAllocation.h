// Allocation failure on demand, for the tests that check what a failed
// allocation does: the global operator new (and new[], plain and aligned,
// throwing and nothrow) replaced so that the k-th allocation of at least
// kLarge bytes, counted from a start, throws std::bad_alloc (the nothrow
// forms return null). Include it in exactly one file of a test
// executable (the replacement applies to the whole program).
#ifndef osm_FailingAllocation_h
#define osm_FailingAllocation_h

#include <atomic>
#include <cstdlib>
#include <new>

namespace failing_allocation
{

/// Only allocations of at least this size count: arrays, not the small
/// strings and scratch of bookkeeping.
inline constexpr std::size_t kLarge = 16 * 1024;

inline std::atomic<bool> counting{ false };
inline std::atomic<long> largeSeen{ 0 };
inline std::atomic<long> failAt{ -1 };

/// Counts from now the large allocations, the k-th of which (from 0) fails; -1
/// fails none.
inline void start(long k)
{
  largeSeen = 0;
  failAt = k;
  counting = true;
}

/// Stops counting; returns the large allocations seen since start().
inline long stop()
{
  counting = false;
  return largeSeen.load();
}

inline void failIfChosen(std::size_t n)
{
  if (n >= kLarge && counting.load() && largeSeen.fetch_add(1) == failAt.load())
  {
    throw std::bad_alloc();
  }
}

inline void* allocate(std::size_t n)
{
  failIfChosen(n);
  if (void* p = std::malloc(n == 0 ? 1 : n))
  {
    return p;
  }
  throw std::bad_alloc();
}

/// Over-aligned types (the triangulation's 32-byte slots) come here.
inline void* allocateAligned(std::size_t n, std::align_val_t alignment)
{
  failIfChosen(n);
  const std::size_t a = static_cast<std::size_t>(alignment);
  // aligned_alloc wants a size that is a multiple of the alignment.
  if (void* p = std::aligned_alloc(a, (n + a - 1) / a * a + (n == 0 ? a : 0)))
  {
    return p;
  }
  throw std::bad_alloc();
}

} // namespace failing_allocation

void* operator new(std::size_t n)
{
  return failing_allocation::allocate(n);
}
void* operator new[](std::size_t n)
{
  return failing_allocation::allocate(n);
}
void* operator new(std::size_t n, std::align_val_t a)
{
  return failing_allocation::allocateAligned(n, a);
}
void* operator new[](std::size_t n, std::align_val_t a)
{
  return failing_allocation::allocateAligned(n, a);
}
// std::stable_sort's buffer comes from the nothrow form (and does without
// it): replaced too, so that every form frees what its own form allocated
// (AddressSanitizer saw the library's nothrow new freed here).
void* operator new(std::size_t n, const std::nothrow_t&) noexcept
{
  try
  {
    return failing_allocation::allocate(n);
  }
  catch (const std::bad_alloc&)
  {
    return nullptr;
  }
}
void* operator new[](std::size_t n, const std::nothrow_t& tag) noexcept
{
  return operator new(n, tag);
}
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept
{
  try
  {
    return failing_allocation::allocateAligned(n, a);
  }
  catch (const std::bad_alloc&)
  {
    return nullptr;
  }
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t& tag) noexcept
{
  return operator new(n, a, tag);
}
void operator delete(void* p, const std::nothrow_t&) noexcept
{
  std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept
{
  std::free(p);
}
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept
{
  std::free(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept
{
  std::free(p);
}
void operator delete(void* p) noexcept
{
  std::free(p);
}
void operator delete[](void* p) noexcept
{
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept
{
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept
{
  std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept
{
  std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept
{
  std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept
{
  std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept
{
  std::free(p);
}

#endif
