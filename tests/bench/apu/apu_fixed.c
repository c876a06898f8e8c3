/* apu_fixed.c: Table 1's operations in the fixed build's arithmetic
 * (fixed/num.h, compiled with LINKS1_NUM_FIXED: num_add, num_mul). */
#include "fixed/num.h"
#include "tests/bench/apu/apu.h"

void apu_fixed(int op, const int32_t *a, const int32_t *b, int32_t *r)
{
    switch (op) {
    case APU_VADD:
        for (int i = 0; i < 3; i++)
            r[i] = num_add(a[i], b[i]);
        break;
    case APU_VDOT:
        r[0] = num_add(num_add(num_mul(a[0], b[0]), num_mul(a[1], b[1])), num_mul(a[2], b[2]));
        break;
    case APU_MADD:
        for (int i = 0; i < 9; i++)
            r[i] = num_add(a[i], b[i]);
        break;
    case APU_MMUL:
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                r[3 * i + j] = num_add(num_add(num_mul(a[3 * i], b[j]), num_mul(a[3 * i + 1], b[3 + j])),
                                       num_mul(a[3 * i + 2], b[6 + j]));
        break;
    }
}

int32_t apu_fixed_one(void)
{
    return NUM_ONE_RAW;
}
