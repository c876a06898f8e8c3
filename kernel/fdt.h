/* fdt.h: just enough of a flattened device tree reader to learn the RAM
 * QEMU gave the board.  QEMU places the tree at the start of RAM when the
 * ELF image leaves room there (linker/virt-memory.ld keeps the first MiB
 * free).  No hardware access: the host tests build it. */
#ifndef LINKS1_KERNEL_FDT_H
#define LINKS1_KERNEL_FDT_H

#include <stddef.h>
#include <stdint.h>

enum fdt_status {
    FDT_OK = 0,
    FDT_ERR_MAGIC = -1,     /* no device tree there */
    FDT_ERR_TRUNCATED = -2, /* a structure runs past the blob */
    FDT_ERR_NO_MEMORY = -3, /* no memory node with a usable reg */
};

/* Finds the first "memory" node's reg (2 address and 2 size cells, as on
 * the virt board) in the blob at fdt, at most cap bytes long. */
int fdt_find_memory(const uint8_t *fdt, size_t cap, uint64_t *base, uint64_t *size);
const char *fdt_strerror(int status);

#endif
