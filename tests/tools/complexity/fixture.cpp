// tools/complexity.py's fixture: each function's name says the cyclomatic complexity it has
// (1 + each if, for, range-for, while, do, case, catch, ?:, && and ||), each kind of decision used;
// the comments count the decisions so far.
// complexity_test.sh checks the tool reports exactly the ones over its limit, with these numbers.
#include <stdexcept>
#include <vector>

// 1 + 24 decisions = 25: at the limit, not over it.
int at25(int a, int b, const std::vector<int>& v) {
  int n = 0;
  if (a > 0) ++n;                   // 1
  if (a > 1 && b > 1) ++n;          // 3
  if (a > 2 || b > 2) ++n;          // 5
  n += a > 3 ? 1 : 0;               // 6
  for (int i = 0; i < a; ++i) ++n;  // 7
  for (const int x : v) n += x;     // 8
  while (n > 100) n /= 2;           // 9
  do --n;                           // 10
  while (n > 50);
  switch (b) {
    case 0:
      ++n;
      break;  // 11
    case 1:
      n += 2;
      break;  // 12
    default:
      break;
  }
  try {
    if (n < 0) throw std::runtime_error("n");  // 13
  } catch (const std::runtime_error&) {        // 14
    n = 0;
  }
  auto inner = [&](int k) { return k > 0 && k < 9 ? k : 0; };  // 16: a lambda's count is its holder's
  n += inner(a);
  if (a == 5 || a == 6 || a == 7 || a == 8) ++n;  // 20
  if (b == 5 && b != 6 && b != 7 && b != 8) ++n;  // 24
  return n;
}

// The same and one if more: 26, over.
int over26(int a, int b, const std::vector<int>& v) {
  int n = at25(a, b, v);
  if (a > 0) ++n;                   // 1
  if (a > 1 && b > 1) ++n;          // 3
  if (a > 2 || b > 2) ++n;          // 5
  n += a > 3 ? 1 : 0;               // 6
  for (int i = 0; i < a; ++i) ++n;  // 7
  for (const int x : v) n += x;     // 8
  while (n > 100) n /= 2;           // 9
  do --n;                           // 10
  while (n > 50);
  switch (b) {
    case 0:
      ++n;
      break;  // 11
    case 1:
      n += 2;
      break;  // 12
    default:
      break;
  }
  try {
    if (n < 0) throw std::runtime_error("n");  // 13
  } catch (const std::runtime_error&) {        // 14
    n = 0;
  }
  auto inner = [&](int k) { return k > 0 && k < 9 ? k : 0; };  // 16
  n += inner(a);
  if (a == 5 || a == 6 || a == 7 || a == 8) ++n;  // 20
  if (b == 5 && b != 6 && b != 7 && b != 8) ++n;  // 24
  if (a == 9) ++n;                                // 25
  return n;
}

// Bitwise operators and rvalue references are no decisions.
int plain(int&& a, int b) { return (a & b) | (a ^ b); }
