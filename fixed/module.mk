# fixed/: the renderer's number type num_t (double, float or fixed point).
SHARED_SRCS += fixed/num.c

# Number tests, once per arithmetic.
test_num_double_SRCS := tests/host/test_num.c
test_num_double_ARITH := double
test_num_float_SRCS := tests/host/test_num.c
test_num_float_ARITH := float
test_num_fixed_SRCS := tests/host/test_num.c
test_num_fixed_ARITH := fixed

# The one integer square root (fixed point's num_sqrt, the RC's area
# schedules), checked against its definition.
SHARED_SRCS += fixed/isqrt.c
ARITH_FREE_SRCS += fixed/isqrt.c
test_isqrt_SRCS := tests/host/test_isqrt.c
test_isqrt_ARITH := double

# The fixed point's division, square roots and dot product against plain
# exact references, bit for bit, in every fixed format built.
# They link the fixed point alone (NAME_SHARED).
test_num_exact_SRCS := tests/host/test_num_exact.c
test_num_exact_ARITH := fixed
test_num_exact_SHARED := fixed/num.c fixed/isqrt.c
$(foreach f,12 14 16 18,$(eval test_num_exact_fixed$(f)_SRCS := tests/host/test_num_exact.c)$(eval test_num_exact_fixed$(f)_ARITH := fixed$(f))$(eval test_num_exact_fixed$(f)_SHARED := $(test_num_exact_SHARED)))
