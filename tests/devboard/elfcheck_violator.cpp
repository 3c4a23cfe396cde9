// Breaks the firmware rules on purpose (float arithmetic, a heap call) so the ELF check is seen
// to catch them.
#include <stddef.h>

#include <qr/boards/rv32virt/devboard.hpp>

extern "C" [[gnu::noinline, gnu::used]] void* malloc(size_t size);
extern "C" void* malloc(size_t size) {  // never called; only its presence matters
  static unsigned char pool[16];
  return size <= sizeof pool ? pool : nullptr;
}

volatile float g_x = 1.5f;
void* volatile g_heap = nullptr;

int main() {
  g_x = g_x / 3.0f;
  if (g_x > 100.0f) g_heap = malloc(4);
  return 0;
}
