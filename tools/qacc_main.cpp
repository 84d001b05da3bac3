// qacc command line (design §7).
#include <cstdio>

int main() {
  std::puts("qacc");
  return 0;
}
