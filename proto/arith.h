/* arith.h: the arithmetics links1 renders in, as one code for the firmware
 * (its LINK_HELLO names the build's arithmetic), the host tools (--arith)
 * and the board checks.  The numbers travel in LINK_HELLO: do not renumber.
 *
 *   float   hardware VFP (board), the float build (host)
 *   soft    IEEE binary32 in software (board); on the host the float build
 *   fixed   fixed point (fixed/num.h)
 *   double  hardware VFP in double precision (board), the host's reference */
#ifndef LINKS1_PROTO_ARITH_H
#define LINKS1_PROTO_ARITH_H

enum links1_arith {
    ARITH_FLOAT = 0,
    ARITH_SOFT = 1,
    ARITH_FIXED = 2,
    ARITH_DOUBLE = 3,
};
#define ARITH_COUNT 4
/* Codes below this have board firmware (build/links1-<name>.elf). */
#define ARITH_BOARD_COUNT 4

/* "float", "soft", "fixed", "double"; NULL for a code out of range. */
const char *arith_name(int arith);
/* The code of a name, or -1 for an unknown name. */
int arith_from_name(const char *name);
/* 1 when the board has firmware for this code. */
static inline int arith_on_board(int arith)
{
    return arith >= 0 && arith < ARITH_BOARD_COUNT;
}

#endif
