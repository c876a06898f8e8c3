# tests/sweeps/: where each arithmetic breaks (scene families of
# host-tools/gen/make_scene.py, sweep.sh) and the speed-against-accuracy chart (pareto.sh).
# (make test runs them at reduced size: tests/plan.tsv names those scripts.)

# make sweeps: the full sweeps; tables and charts into docs/figures/.
.PHONY: sweeps
sweeps: deps
	$(Q)$(MAKE) $(JOBS) --no-print-directory all
	$(Q)bash tests/sweeps/sweep.sh --out $(B)/sweeps
	$(Q)mkdir -p docs/figures && cp $(B)/sweeps/sweep-*.png docs/figures/ && \
		cp $(B)/sweeps/breaks.md docs/figures/sweep-breaks.md && \
		cp $(B)/sweeps/sweep.tsv docs/figures/sweep.tsv

# make sweeps-auto: --arith auto on every sweep scene against the cheapest
# candidate that keeps 40 dB (tests/sweeps/auto.sh; 10 minutes in its last run): every
# scene in sweep-auto.tsv, a row a family in sweep-auto.md.
.PHONY: sweeps-auto
sweeps-auto: deps
	$(Q)$(MAKE) $(JOBS) --no-print-directory all
	$(Q)bash tests/sweeps/auto.sh --out $(B)/sweeps-auto
	$(Q)mkdir -p docs/figures && cp $(B)/sweeps-auto/auto.tsv docs/figures/sweep-auto.tsv && \
		cp $(B)/sweeps-auto/auto.md docs/figures/sweep-auto.md

# make sweeps-auto-model: --auto (arithmetic, min_weight and density steps)
# on every sweep scene against the cheapest configuration that keeps 40 dB
# at full size (tests/sweeps/auto_model.sh; docs/results/arith-auto.md): every
# scene in sweep-auto-model.tsv, a row a family in sweep-auto-model.md.
.PHONY: sweeps-auto-model
sweeps-auto-model: deps
	$(Q)$(MAKE) $(JOBS) --no-print-directory all
	$(Q)bash tests/sweeps/auto_model.sh --out $(B)/sweeps-auto-model
	$(Q)mkdir -p docs/figures && \
		cp $(B)/sweeps-auto-model/auto_model.tsv docs/figures/sweep-auto-model.tsv && \
		cp $(B)/sweeps-auto-model/auto_model.md docs/figures/sweep-auto-model.md
