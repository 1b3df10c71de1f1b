// Medium blocks of the mesher's arrays, carved from huge pages during a call.
//
// Blocks from kPooledBytes up to pages::kOwnMappingBytes are too small for a
// mapping of their own, but a mesh of 10^3 to 10^5 triangles has dozens of
// them, and from operator new each one is fresh small pages: on a virtual
// machine every first touch of a small page costs about 10 us, so that
// random-segments 1e3 spent a third of its time in 240 page faults. While a
// pages::Reuse scope lives, such blocks come instead from chunks of the pool's
// own, each one 2 MiB huge page, and freed blocks are handed out again. The
// blocks asked for in a scope before its first one of kFirstPooledBytes or
// more still come from operator new, so that small meshes do not clear a huge
// page for a few blocks. Outside a scope, and with huge pages turned off,
// operator new serves them all.
//
// A block handed out in a scope may outlive it (a Result's arrays): its chunk
// then stays mapped and whole (2 MiB resident, its free parts unused) until
// its last block is freed. A block is the pool's if it lies in one of its chunks, so
// operator new's blocks are never mistaken for the pool's.
#ifndef osm_BlockPool_h
#define osm_BlockPool_h

#include <cstddef>

namespace osm
{
namespace pool
{

/// Blocks from this size up (and below pages::kOwnMappingBytes) are pooled.
constexpr std::size_t kPooledBytes = std::size_t{ 4 } << 10;

/// A scope pools from its first block of this size on (a mesh of about a
/// thousand triangles); the blocks before come from operator new.
constexpr std::size_t kFirstPooledBytes = std::size_t{ 32 } << 10;

/// A block of at least bytes (rounded up to whole small pages) while a scope
/// lives and pools, or null: the caller then takes it from operator new (also
/// when a chunk cannot be mapped).
void* take(std::size_t bytes);

/// Frees a block if it is the pool's (then returns true), else returns false.
bool give(void* p, std::size_t bytes) noexcept;

/// Chunks mapped now (for tests).
std::size_t chunks();

/// Called by pages::Reuse: the pool serves blocks while at least one scope is
/// open; when the last closes, chunks with no live block are given back.
void openScope();
void closeScope() noexcept;

} // namespace pool
} // namespace osm

#endif
