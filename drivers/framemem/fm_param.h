/* fm_param.h: every limit of the data collector (DC) and the frame memory
 * (FM) in one place. */
#ifndef LINKS1_DRIVERS_FRAMEMEM_FM_PARAM_H
#define LINKS1_DRIVERS_FRAMEMEM_FM_PARAM_H

/* Frame memory: LINKS-1 built 1024x1024 (two 1024x512 blocks), 8 bits per
 * channel.  Each pixel is held in a 32-bit word, 0x00RRGGBB, so the memory
 * is also a framebuffer ramfb can show without a copy (fourcc XR24). */
#define FM_MAX_WIDTH 1024u
#define FM_MAX_HEIGHT 1024u
#define FM_BYTES_PER_PIXEL 4u

/* Data collector FIFO: slots of one pixel run each.  A run is at most
 * DC_RUN_MAX_PIXELS pixels of one scanline (a wider span is pushed as
 * several runs): small enough that a slot is cheap, large enough that the
 * per-run cost is spread over many pixels (the paper's lesson from the APU:
 * batch the hand-offs).  Slots: power of two. */
#define DC_RUN_MAX_PIXELS 64u
#define DC_RING_SLOTS 256u

/* Producers are named by core number, below this bound (kernel/param.h
 * UNITS_MAX_CORES; the host tests use thread numbers). */
#define DC_MAX_PRODUCERS 256u

/* fw_cfg file directory entries read before giving up on finding a file
 * (QEMU lists a few dozen; a larger count means a misread directory). */
#define FWCFG_MAX_FILES 4096u

#endif
