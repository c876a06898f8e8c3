/* fm_view_none.c: the an521 boards have no display (fm_view.h). */
#include "drivers/framemem/fm_view.h"

int fm_view_show(const struct fm *fm, const char **why)
{
    (void)fm;
    (void)why;
    return FM_VIEW_ABSENT;
}
