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

/* Traps. An exception never returns (fail_safe.cpp) and may be the stack running into its guard,
   so it leaves the stack it came on for the fault stack (link.ld) before touching memory.
   Interrupts save the caller-saved registers on the stack they interrupted, let C++ handle them,
   restore and return; the callee-saved ones are kept by the C++ code itself. */
  .align 4
  .globl rv32virt_trap_entry
rv32virt_trap_entry:
  csrw mscratch, t0
  csrr t0, mcause
  bgez t0, rv32virt_exception_entry  /* mcause bit 31 clear: an exception */
  csrr t0, mscratch
  addi sp, sp, -64
  sw ra, 0(sp)
  sw t0, 4(sp)
  sw t1, 8(sp)
  sw t2, 12(sp)
  sw a0, 16(sp)
  sw a1, 20(sp)
  sw a2, 24(sp)
  sw a3, 28(sp)
  sw a4, 32(sp)
  sw a5, 36(sp)
  sw a6, 40(sp)
  sw a7, 44(sp)
  sw t3, 48(sp)
  sw t4, 52(sp)
  sw t5, 56(sp)
  sw t6, 60(sp)
  csrr a0, mcause
  call rv32virt_interrupt
  lw ra, 0(sp)
  lw t0, 4(sp)
  lw t1, 8(sp)
  lw t2, 12(sp)
  lw a0, 16(sp)
  lw a1, 20(sp)
  lw a2, 24(sp)
  lw a3, 28(sp)
  lw a4, 32(sp)
  lw a5, 36(sp)
  lw a6, 40(sp)
  lw a7, 44(sp)
  lw t3, 48(sp)
  lw t4, 52(sp)
  lw t5, 56(sp)
  lw t6, 60(sp)
  addi sp, sp, 64
  mret

rv32virt_exception_entry:
  la sp, __fault_stack_top
  csrr a0, mcause
  csrr a1, mepc
  csrr a2, mtval
  call rv32virt_exception
2:j 2b
