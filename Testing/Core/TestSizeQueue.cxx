// The SVR refinement queue: larger size classes first, newest first within a
// class, every item popped exactly once, extreme keys handled.
#include "SizeQueue.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace osm;

TEST(SizeQueue, PopsLargerClassesFirstAndNewestFirstWithinAClass)
{
  SizeQueue<int> q;
  EXPECT_TRUE(q.empty());
  q.push(1.0, 1);  // class of r^2 in [1, 64)
  q.push(48.0, 2); // same class
  q.push(64.0, 3); // the next larger class
  q.push(0.99, 4); // the next smaller class
  EXPECT_EQ(q.pop(), 3);
  EXPECT_EQ(q.pop(), 2); // newest of its class
  EXPECT_EQ(q.pop(), 1);
  q.push(5000.0, 5); // pushing a larger class after pops still comes first
  EXPECT_EQ(q.pop(), 5);
  EXPECT_EQ(q.pop(), 4);
  EXPECT_TRUE(q.empty());
}

TEST(SizeQueue, OrdersWithinASizeClassAndLosesNothing)
{
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> exponent(-300, 300);
  SizeQueue<int> q;
  std::vector<double> keys;
  for (int i = 0; i < 5000; ++i)
  {
    keys.push_back(std::pow(10.0, exponent(rng)));
    q.push(keys.back(), i);
  }
  std::vector<char> seen(keys.size(), 0);
  // A class spans 2^kExponentsPerClass in r^2 (a factor of 8 in r).
  const double classRatio = std::ldexp(1.0, SizeQueue<int>::kExponentsPerClass);
  double smallest = std::numeric_limits<double>::infinity();
  while (!q.empty())
  {
    const int i = q.pop();
    ASSERT_FALSE(seen[i]) << "popped twice: " << i;
    seen[i] = 1;
    // No later key may be more than a size class above an earlier one.
    EXPECT_LE(keys[i], classRatio * smallest) << i;
    smallest = std::min(smallest, keys[i]);
  }
  for (char s : seen)
    EXPECT_TRUE(s);
}

TEST(SizeQueue, ExtremeKeys)
{
  SizeQueue<int> q;
  q.push(std::numeric_limits<double>::quiet_NaN(), 1);
  q.push(0.0, 2);
  q.push(std::numeric_limits<double>::denorm_min(), 3);
  q.push(std::numeric_limits<double>::max(), 4);
  q.push(std::numeric_limits<double>::infinity(), 5);
  EXPECT_EQ(q.pop(), 5);
  EXPECT_EQ(q.pop(), 4);
  EXPECT_EQ(q.pop(), 3);
  EXPECT_EQ(q.pop(), 2); // NaN and 0 share the smallest class, newest first
  EXPECT_EQ(q.pop(), 1);
  // Pushed the other way round, so that newest-first within a class cannot
  // give the same order (a mutation test): infinity has a class above the
  // largest double's, and the smallest subnormal one above 0's.
  q.push(std::numeric_limits<double>::infinity(), 6);
  q.push(std::numeric_limits<double>::max(), 7);
  q.push(std::numeric_limits<double>::denorm_min(), 8);
  q.push(0.0, 9);
  EXPECT_EQ(q.pop(), 6);
  EXPECT_EQ(q.pop(), 7);
  EXPECT_EQ(q.pop(), 8);
  EXPECT_EQ(q.pop(), 9);
  EXPECT_TRUE(q.empty());
}

TEST(SizeQueue, SubnormalKeysKeepTheirSizeOrder)
{
  // Subnormal squared radii have no exponent field to read: they must still
  // fall into classes by their true exponent, below the normal numbers.
  SizeQueue<int> q;
  q.push(std::ldexp(1.0, -1030), 1); // subnormal, several classes above...
  q.push(std::ldexp(1.0, -1074), 2); // ...the smallest positive double
  q.push(std::ldexp(1.0, -1000), 3); // normal
  EXPECT_EQ(q.pop(), 3);
  EXPECT_EQ(q.pop(), 1); // were both subnormals in one class, 2 (newest) would come first
  EXPECT_EQ(q.pop(), 2);
  EXPECT_TRUE(q.empty());
}
