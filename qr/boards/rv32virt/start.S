/* Reset entry: global pointer, stack, trap vector, then C++ (runtime.cpp). */
  .section .text.start, "ax"
  .globl _start
_start:
  .option push
  .option norelax
  la gp, __global_pointer$
  .option pop
  la sp, __stack_top
  la t0, rv32virt_trap_entry
  csrw mtvec, t0
  call rv32virt_start
1:j 1b

/* Any exception ends the run: the C++ side reports mcause/mepc and exits with failure. */
  .align 4
  .globl rv32virt_trap_entry
rv32virt_trap_entry:
  la sp, __stack_top
  csrr a0, mcause
  csrr a1, mepc
  csrr a2, mtval
  call rv32virt_trap
2:j 2b
