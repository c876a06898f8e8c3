# render/: the ray tracer, built for every arithmetic; it knows nothing of
# cores, drivers or messages.
SHARED_SRCS += render/arena.c render/xform.c render/prim.c render/prepare.c \
	render/shade.c render/maps.c render/trace.c

# Renderer tests, once per arithmetic.
HOST_TESTS += test_prim_double test_prim_float test_prim_fixed
test_prim_double_SRCS := tests/host/test_prim.c
test_prim_double_ARITH := double
test_prim_float_SRCS := tests/host/test_prim.c
test_prim_float_ARITH := float
test_prim_fixed_SRCS := tests/host/test_prim.c
test_prim_fixed_ARITH := fixed
HOST_TESTS += test_shade_double test_shade_float test_shade_fixed
test_shade_double_SRCS := tests/host/test_shade.c
test_shade_double_ARITH := double
test_shade_float_SRCS := tests/host/test_shade.c
test_shade_float_ARITH := float
test_shade_fixed_SRCS := tests/host/test_shade.c
test_shade_fixed_ARITH := fixed
HOST_TESTS += test_render_double test_render_float test_render_fixed
test_render_double_SRCS := tests/host/test_render.c
test_render_double_ARITH := double
test_render_float_SRCS := tests/host/test_render.c
test_render_float_ARITH := float
test_render_fixed_SRCS := tests/host/test_render.c
test_render_fixed_ARITH := fixed

# Host speed per arithmetic (wall clock: `make bench`, never a test).
BENCHES += render/bench-host.sh
