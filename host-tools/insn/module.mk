# host-tools/insn/: guest instructions counted by a QEMU TCG plugin, and
# the report of its counts.
HT_INSN_SRCS := host-tools/insn/insn_report.c
ARITH_FREE_SRCS += $(HT_INSN_SRCS)

# The TCG plugin is loaded into QEMU: a plain shared object, no sanitizers.
INSN_PLUGIN := $(B)/insn-count.so
$(INSN_PLUGIN): host-tools/insn/insn_count_plugin.c
	$(call say,HOSTSO,$@)
	$(Q)mkdir -p $(@D)
	$(Q)$(HOST_CC) $(HOST_CFLAGS) -fPIC -shared -fvisibility=hidden $< -o $@
-include $(INSN_PLUGIN:.so=.d)
host-tools: $(INSN_PLUGIN)
