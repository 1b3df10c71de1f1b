// Transparent huge pages for the mesher's large arrays.
//
// The refinement reads and writes its triangle slots in an order the mesh
// decides, all over arrays of hundreds of megabytes: with 4 KiB pages nearly
// every access misses the TLB, and every first touch of a fresh array is a page
// fault (about 300,000 of them at 10^7 triangles, a fifth of the run on a
// virtual machine). 2 MiB pages remove most of both. Debian's kernels give them
// only to memory that asks (transparent_hugepage=madvise), so the mesher asks
// for its own large arrays; the host application's heap stays as it was.
// Where huge pages cost more than they save (a kernel that compacts memory
// on every such fault), OSM_NO_HUGE_PAGES=1 in the environment turns the
// advice off.
#ifndef osm_HugePages_h
#define osm_HugePages_h

#include <cstddef>
#include <vector>

namespace osm
{

/// Asks the kernel to back the whole 2 MiB pages inside [p, p + bytes) with
/// transparent huge pages, where it can (Linux; elsewhere, for ranges without
/// a whole huge page, when the kernel declines, or with OSM_NO_HUGE_PAGES set to
/// anything but 0, nothing changes). Best called before the memory is first
/// touched.
void adviseHugePages(const void* p, std::size_t bytes);

/// Whether the advice is on: OSM_NO_HUGE_PAGES unset, empty or 0.
bool hugePagesWanted();

/// v.reserve(n), then the advice for v's storage.
template <class T>
void reserveHuge(std::vector<T>& v, std::size_t n)
{
  v.reserve(n);
  adviseHugePages(v.data(), v.capacity() * sizeof(T));
}

/// pushBackHuge when v is full: its storage doubles into advised memory.
template <class T>
[[gnu::noinline]] void pushBackGrowingHuge(std::vector<T>& v, const T& x)
{
  const T copy = x; // x may be an element of v, which growing frees
  std::vector<T> bigger;
  reserveHuge(bigger, 2 * v.capacity() + 16);
  bigger.insert(bigger.end(), v.begin(), v.end());
  bigger.push_back(copy);
  v.swap(bigger);
}

/// v.push_back(x); when v is full, its storage doubles into advised memory
/// (for arrays that outgrow their reservation). The growth is apart so that
/// the common case inlines: the refinement pushes a slot or an item per step.
template <class T>
inline void pushBackHuge(std::vector<T>& v, const T& x)
{
  if (v.size() == v.capacity())
    pushBackGrowingHuge(v, x);
  else
    v.push_back(x);
}

/// v.assign(n, value) on storage advised before it is filled.
template <class T>
void assignHuge(std::vector<T>& v, std::size_t n, const T& value)
{
  if (v.capacity() < n)
  {
    std::vector<T>().swap(v);
    reserveHuge(v, n);
  }
  v.assign(n, value);
}

} // namespace osm

#endif
