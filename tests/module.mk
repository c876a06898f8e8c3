# tests/: the build rules of the host unit tests of tests/host/ (built with
# ASan+UBSan), the benchmarks and the targets of tests/.  What runs is
# tests/plan.tsv's.
test_crc32_SRCS := tests/host/test_crc32.c
test_crc32_ARITH := double
test_wordsum_SRCS := tests/host/test_wordsum.c
test_wordsum_ARITH := double

# RC area schedules (proto/areas.c): pure, so tested on the host.
test_areas_SRCS := tests/host/test_areas.c
test_areas_ARITH := double

# Data collector FIFO, frame memory and fw_cfg/ramfb formats
# (drivers/framemem/): the hardware-free parts, tested on the host.
test_framemem_SRCS := tests/host/test_framemem.c drivers/framemem/fm.c \
	drivers/framemem/dc_ring.c drivers/framemem/dc_selftest_pattern.c
test_framemem_ARITH := double
test_framemem_LIBS := -lpthread
test_fwcfg_SRCS := tests/host/test_fwcfg.c drivers/virt/fwcfg_format.c
test_fwcfg_ARITH := double


# Host speed per arithmetic (wall clock, never a test), then the board's.
BENCHES += tests/bench/bench_host.sh
BENCHES += tests/bench/bench_render.sh tests/bench/bench_arith.sh tests/bench/bench_scale.sh
# Issue 12: failed NCs (the time a failure costs a frame), the long soak run.
BENCHES += tests/bench/bench_faults.sh tests/bench/bench_soak.sh
BENCHES += tests/bench/bench_big.sh tests/bench/bench_an521.sh
# The DM's preparation hidden behind the NCs' rendering (an animation, traced frame by frame).
BENCHES += tests/bench/bench_pipeline.sh
# links1 farm's own cost, one host against two, and the model of H hosts (wall time).
BENCHES += tests/bench/bench_farm.sh
# Escalation: cost and accuracy of float and fixed with --escalate.
BENCHES += tests/bench/bench_escalate.sh
# Anti-aliasing: NC instructions a pixel against error to a 16x16 supersampled reference.
BENCHES += tests/bench/bench_aa.sh
# The board cost model --arith auto does not use: work counts against NC instructions.
BENCHES += tests/bench/arith_cost_fit.sh
BENCHES += tests/bench/bench_link_noise.sh
# Issue 20: the DM's and the RC's instructions per triangle of a frame.
BENCHES += tests/bench/bench_board_scale.sh
# The DM in eye space and in world space (--world-space) on an animation whose camera moves.
BENCHES += tests/bench/bench_world.sh
# Issue 39: links1 ref against POV-Ray 3.7 given the NFF's own primitives on the seven SPD databases.
BENCHES += tests/bench/bench_spd_pov.sh

# links1 compare --flags: precision and recall of a render's flags.
test_image_flags_SRCS := tests/host/test_image_flags.c host-tools/image/image_compare.c
test_image_flags_ARITH := double

# Encodings of the rendering commands and the NC statistics the RC sums.
test_render_link_SRCS := tests/host/test_render_link.c host-tools/gigs/render_faults.c
test_render_link_ARITH := float

BENCHES += tests/bench/bench_figures.sh
# The paper's Table 1 on two cores (docs/results/paper-figures.md).
BENCHES += tests/bench/bench_apu.sh

# make figures: the paper's figures and tables (tests/bench/figures.sh) and
# the chart of speed against accuracy (tests/sweeps/pareto.sh) into docs/figures.
.PHONY: figures
figures: deps
	$(Q)$(MAKE) $(JOBS) --no-print-directory all
	$(Q)FW_DIR=$(FWB) bash tests/bench/figures.sh
	$(Q)FW_DIR=$(FWB) bash tests/sweeps/pareto.sh --out $(B)/pareto
	$(Q)mkdir -p docs/figures && cp $(B)/pareto/pareto.png $(B)/pareto/pareto.tsv \
		$(B)/pareto/pareto-board.png $(B)/pareto/pareto-board.tsv docs/figures/
BENCHES += tests/bench/bench_wallclock.sh

# The include rules of docs/layers.md (tests/layers/layers.sh in make test).
.PHONY: check-layers
check-layers:
	$(Q)bash tests/layers/check_layers.sh

# Deliberate faults, each in a copy of the tree: every one must make a test
# fail, of `make test` or one a mutant's try: line names from `make
# test-full` (tests/mutants/; not part of `make test`).
.PHONY: test-mutants
test-mutants: deps
	$(Q)$(MAKE) $(JOBS) --no-print-directory all $(HOST_TEST_BINS) $(FUZZ_BINS)
	$(Q)HOST_TESTS="$(HOST_TEST_BINS)" \
		BOARD_TESTS="$(BOARD_TESTS) $(filter-out build/tests/%,$(FULL_TESTS))" FW_DIR=$(FWB) \
		python3 tests/mutants/mutants.py

# The C unit tests that have a build rule (a test_NAME_SRCS), one a line:
# tests/runner/plan_rows.sh holds them against the plan.
.PHONY: test-progs-with-rules
test-progs-with-rules:
	@printf '%s\n' $(sort $(patsubst %_SRCS,%,$(filter test_%_SRCS,$(.VARIABLES))))
