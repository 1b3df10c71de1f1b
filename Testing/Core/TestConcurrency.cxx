// Concurrent calls of osm::mesh: a VTK application may mesh in two
// pipelines on two threads. Every call must give, bit for bit, what the same
// call gives alone, while the process-wide memory pools are shared; results
// may be freed on another thread than the one that made them, while others
// mesh. .ci/reliability runs it under ThreadSanitizer, which reports any
// data race.
#include "Mesher.h"
#include "PolyReader.h"
#include "RunContext.h"
#include "SharedData.h"

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace osm
{
namespace
{

struct Case
{
  std::string name;
  Pslg input;
  Options options;
};

/// Random points in the unit square inside a square with a square hole:
/// the overlay, stitching, completion and carving all have work to do.
Pslg squareWithPoints(unsigned seed, int count)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> at(0.05, 0.95);
  Pslg p;
  p.points = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 }, { 0.4, 0.4 }, { 0.6, 0.4 }, { 0.6, 0.6 },
    { 0.4, 0.6 } };
  p.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 }, { 5, 6 }, { 6, 7 }, { 7, 4 } };
  p.holes = { { 0.5, 0.5 } };
  while (static_cast<int>(p.points.size()) < count)
  {
    const Point q{ at(rng), at(rng) };
    if (q.x < 0.38 || q.x > 0.62 || q.y < 0.38 || q.y > 0.62)
      p.points.push_back(q);
  }
  return p;
}

std::vector<Case> cases()
{
  std::vector<Case> all;
  // From a few hundred to some 10^5 triangles: small meshes allocate from
  // the heap, larger ones from the shared huge-page pool and mapping reuse.
  for (const int count : { 40, 400, 4000, 20000 })
    all.push_back({ "square " + std::to_string(count), squareWithPoints(count, count), {} });
  Options bounded;
  bounded.maxEdgeLength = 0.02;
  bounded.domain = Domain::Hull;
  all.push_back({ "square with a size bound", squareWithPoints(7, 300), bounded });
  // A few real inputs, where present (the tests skip nothing without them).
  for (const auto& file : shared_data::polyFiles())
  {
    const std::string name = file.filename().string();
    if (name != "A.poly" && name != "guitar.poly" && name != "lake_superior.poly" &&
      name != "Constrained_Sweden.poly")
      continue;
    const PolyFile read = readPolyFile(file.string());
    if (read.ok)
      all.push_back({ name, read.pslg, {} });
  }
  return all;
}

/// Whether two results are the same mesh, bit for bit.
::testing::AssertionResult sameMesh(const Result& a, const Result& b)
{
  if (a.ok != b.ok || a.error != b.error || a.warnings != b.warnings)
    return ::testing::AssertionFailure()
      << "status or messages differ: '" << a.error << "' vs '" << b.error << "'";
  if (a.mesh.triangles != b.mesh.triangles || a.regionId != b.regionId ||
    a.vertexOrigin != b.vertexOrigin || a.edges.size() != b.edges.size())
    return ::testing::AssertionFailure() << "triangles, regions or edges differ";
  for (std::size_t i = 0; i < a.mesh.vertices.size(); ++i)
    if (a.mesh.vertices[i].x != b.mesh.vertices[i].x ||
      a.mesh.vertices[i].y != b.mesh.vertices[i].y)
      return ::testing::AssertionFailure() << "vertex " << i << " differs";
  return ::testing::AssertionSuccess();
}

/// Aborts on its n-th poll.
class AbortAfter : public Progress
{
public:
  explicit AbortAfter(int polls)
    : Left(polls)
  {}
  void report(double, const char*) override {}
  bool aborted() override { return --this->Left < 0; }

private:
  int Left;
};

TEST(Concurrency, MeshesOnSeveralThreadsAreTheMeshesOfOneThread)
{
  const std::vector<Case> all = cases();
  std::vector<Result> alone;
  for (const Case& c : all)
  {
    alone.push_back(mesh(c.input, c.options));
    ASSERT_TRUE(alone.back().ok) << c.name << ": " << alone.back().error;
  }
  constexpr int threads = 4, rounds = 3;
  // Each thread meshes every case, starting at a different one, posts every
  // other result to a mailbox and frees what the others posted there, while
  // they mesh: results outlive their thread's calls and are freed on threads
  // that have a call of their own open or not (the memory pools' two paths).
  std::mutex mailboxLock;
  std::vector<Result> mailbox;
  std::atomic<int> freedElsewhere{ 0 };
  std::vector<std::string> failures(threads);
  std::atomic<int> aborted{ 0 };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([&, t] {
      for (int r = 0; r < rounds; ++r)
        for (std::size_t k = 0; k < all.size(); ++k)
        {
          const std::size_t i = (k + static_cast<std::size_t>(t)) % all.size();
          Result got = mesh(all[i].input, all[i].options);
          if (const auto same = sameMesh(got, alone[i]); !same)
            failures[t] +=
              all[i].name + " on thread " + std::to_string(t) + ": " + same.message() + "\n";
          // An aborted call among them gives back what it took.
          AbortAfter stop(3 + t);
          if (mesh(all[i].input, all[i].options, &stop).error == kAbortedByTheUser)
            ++aborted;
          std::vector<Result> theirs;
          {
            const std::lock_guard<std::mutex> lock(mailboxLock);
            theirs.swap(mailbox);
            if (k % 2 == 0)
              mailbox.push_back(std::move(got));
          }
          freedElsewhere += static_cast<int>(theirs.size());
          // theirs (made by other threads, or this one) is freed here.
        }
    });
  for (std::thread& th : pool)
    th.join();
  for (const std::string& f : failures)
    EXPECT_EQ(f, "");
  EXPECT_GT(aborted.load(), 0) << "no call was aborted: the abort path was not exercised";
  EXPECT_GT(freedElsewhere.load(), 0) << "no result was freed while others meshed";
}

} // namespace
} // namespace osm
