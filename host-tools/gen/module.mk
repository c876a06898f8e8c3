# host-tools/gen/: the generators of scenes and data (scripts, no C).  The
# scenes they make are built, not kept: build/scenes/NAME.scn is written by
# make_NAME.py (city, fig9), and the maps of scenes/maps/ are copied beside
# them into build/scenes/maps/ (a scene names its maps relative to its own
# folder).  `make all` makes them.
GEN_SCENES += $(B)/scenes/city.scn $(B)/scenes/fig9.scn
GEN_MAPS := $(patsubst scenes/maps/%,$(B)/scenes/maps/%,$(wildcard scenes/maps/*.png))

$(B)/scenes/%.scn: host-tools/gen/make_%.py | $(GEN_MAPS)
	$(call say,GEN,$@)
	$(Q)mkdir -p $(@D)
	$(Q)python3 $< $@.part && mv $@.part $@

$(B)/scenes/maps/%.png: scenes/maps/%.png
	$(call say,CP,$@)
	$(Q)mkdir -p $(@D)
	$(Q)cp $< $@
