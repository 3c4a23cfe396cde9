# Cross toolchain for the bare-metal RV32IM flight computer (QEMU `virt` stands in for it).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv32)
set(QR_TARGET "rv32" CACHE STRING "host or rv32" FORCE)

set(CMAKE_C_COMPILER riscv64-unknown-elf-gcc)
set(CMAKE_CXX_COMPILER riscv64-unknown-elf-g++)
set(CMAKE_ASM_COMPILER riscv64-unknown-elf-gcc)
set(CMAKE_OBJCOPY riscv64-unknown-elf-objcopy CACHE FILEPATH "")
set(CMAKE_SIZE riscv64-unknown-elf-size CACHE FILEPATH "")

set(QR_RV32_ARCH "-march=rv32im_zicsr -mabi=ilp32")
set(QR_RV32_FREESTANDING "-ffreestanding -fno-exceptions -fno-rtti -fno-threadsafe-statics -fno-asynchronous-unwind-tables -ffunction-sections -fdata-sections")
# Per-function stack frames and call graphs (.su, .ci beside each object) for scripts/elfcheck.
set(QR_RV32_STACK_INFO "-fstack-usage -fcallgraph-info=su")
set(CMAKE_C_FLAGS_INIT "${QR_RV32_ARCH} ${QR_RV32_FREESTANDING}")
set(CMAKE_CXX_FLAGS_INIT "${QR_RV32_ARCH} ${QR_RV32_FREESTANDING} ${QR_RV32_STACK_INFO} -fno-use-cxa-atexit")
set(CMAKE_ASM_FLAGS_INIT "${QR_RV32_ARCH}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${QR_RV32_ARCH} -nostdlib -nostartfiles -Wl,--gc-sections -Wl,--fatal-warnings")

# Only libgcc (integer helpers and soft-float for the float comparison benches) is linked, from
# the rv32im/ilp32 multilib. The `_zicsr` suffix does not match a multilib name, so ask for the
# plain rv32im one.
execute_process(
  COMMAND riscv64-unknown-elf-gcc -march=rv32im -mabi=ilp32 -print-libgcc-file-name
  OUTPUT_VARIABLE QR_RV32_LIBGCC OUTPUT_STRIP_TRAILING_WHITESPACE)
set(QR_RV32_LIBGCC "${QR_RV32_LIBGCC}" CACHE FILEPATH "libgcc of the rv32im/ilp32 multilib")

set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
