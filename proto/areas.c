/* areas.c: the RC's screen-area schedules (see areas.h, docs/areas.md). */
#include "proto/areas.h"

#include <stddef.h>
#include <string.h>

#include "fixed/isqrt.h"

static uint32_t areas_clamp(uint32_t v, uint32_t lo, uint32_t hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

static uint32_t areas_dist(uint32_t a, uint32_t b)
{
    return a > b ? a - b : b - a;
}

/* Bands of scanlines for a grid of k areas on a width x height screen.
 * Square-ish areas need bands of about sqrt(k * height / width); a band count
 * that divides k gives every band the same number of areas (the paper's
 * 32x32 grid), so the nearest divisor is taken when it is within a factor 2
 * of the ideal (on a tie the larger: wider areas clip better in Y), else
 * the ideal itself with bands of k/bands areas rounded up or down.
 * Bounds: every band at least one scanline (bands <= height), no band with
 * more areas than pixels across (bands >= k / width). */
static uint32_t areas_grid_bands(uint32_t width, uint32_t height, uint32_t k)
{
    uint32_t lo = (uint32_t)(((uint64_t)k + width - 1) / width);
    uint32_t hi = k < height ? k : height;
    uint64_t want = (uint64_t)k * height; /* ideal^2 * width */
    uint32_t r0 = (uint32_t)isqrt_u64(want / width);
    /* Round to the nearer of r0 and r0 + 1 by comparing squares. */
    uint64_t below = want - (uint64_t)r0 * r0 * width;
    uint64_t above = (uint64_t)(r0 + 1) * (r0 + 1) * width - want;
    if (above < below)
        r0++;
    r0 = areas_clamp(r0, lo, hi);

    uint32_t best = 0;
    for (uint32_t r = lo; r <= hi; r++)
        if (k % r == 0 && (best == 0 || areas_dist(r, r0) <= areas_dist(best, r0)))
            best = r;
    if (best != 0 && 2 * best >= r0 && best <= 2 * r0)
        return best;
    return r0;
}

/* The pieces a scanline is cut into at target size t: about t each
 * (ceil(width / t) of them), none below the smallest-area bound (at most
 * width / min_pixels, at least one).  Chosen at a scanline's start only:
 * t never grows, so neither do the pieces but by a pixel of rounding. */
static uint32_t areas_pieces(const struct areas *s, uint32_t t)
{
    uint32_t n = (s->width + t - 1) / t, most = s->width / s->min_pixels;
    if (n > most)
        n = most;
    return n ? n : 1;
}

/* Up to max_ncs NCs: k, factor.  From `links1 replay T --ncs N --areas K
 * --guided F` over K from 4096 to 65536 in quarter steps of each power of
 * two (4096, 5120, 6144, 7168, 8192, ...) and F in {1, 2, 3, 4} on ten
 * traces each of demo, glass and molecule at 512x480 (version 4: the
 * replay serves the NCs' MSG_NC_DONEs): the pair whose
 * scenes' median speed-ups are all within the smallest fraction of each
 * scene's best, of equals the one with the largest sum
 * (tests/bench/areas_rule.py, docs/areas.md). */
static const struct {
    uint32_t max_ncs, k, factor;
} areas_decreasing_rule[] = {
    {64, 16384, 2},
    {128, 7168, 4},
    {UINT32_MAX, 14336, 3},
};

void areas_decreasing_defaults(uint32_t ncs, uint32_t *k, uint32_t *factor)
{
    uint32_t i = 0;
    while (ncs > areas_decreasing_rule[i].max_ncs)
        i++;
    *k = areas_decreasing_rule[i].k;
    *factor = areas_decreasing_rule[i].factor;
}

void areas_settings(enum areas_mode mode, uint32_t ncs, uint32_t k, uint32_t factor,
                    uint32_t *k_out, uint32_t *factor_out)
{
    uint32_t rule_k = AREAS_DEFAULT_K, rule_factor = 0; /* grids take no factor */
    if (mode == AREAS_DECREASING)
        areas_decreasing_defaults(ncs, &rule_k, &rule_factor);
    *k_out = mode == AREAS_STATIC ? ncs : (k == 0 ? rule_k : k);
    *factor_out = factor == 0 ? rule_factor : factor;
}

int areas_init(struct areas *s, enum areas_mode mode, uint32_t width, uint32_t height,
               uint32_t ncs, uint32_t k)
{
    memset(s, 0, sizeof *s);
    if (mode != AREAS_STATIC && mode != AREAS_DYNAMIC && mode != AREAS_DECREASING &&
        mode != AREAS_LINES)
        return AREAS_ERR_MODE;
    if (width == 0 || height == 0 || width > AREAS_MAX_DIM || height > AREAS_MAX_DIM)
        return AREAS_ERR_SIZE;
    if (ncs == 0)
        return AREAS_ERR_NCS;

    uint32_t pixels = width * height; /* <= 2^24 by AREAS_MAX_DIM */
    s->mode = mode;
    s->width = width;
    s->height = height;
    s->ncs = ncs;
    areas_settings(mode, ncs, k, 0, &s->k, &s->factor);
    if (s->k > pixels)
        s->k = pixels;
    s->pixels_left = pixels;
    if (mode == AREAS_DECREASING)
        s->min_pixels = (pixels + s->k - 1) / s->k;
    else if (mode == AREAS_LINES) /* one scanline a band, or k bands of whole lines */
        s->bands = s->k < height ? s->k : height;
    else
        s->bands = areas_grid_bands(width, height, s->k);
    return AREAS_OK;
}

/* Area col of band: bands split the scanlines and each band's share of the k
 * areas evenly, cutting at floor(total * i / parts). */
__attribute__((noinline)) static int areas_next_grid(struct areas *s, struct area *a)
{
    if (s->band >= s->bands)
        return 0;
    uint32_t b = s->band;
    uint32_t first = (uint32_t)((uint64_t)s->k * b / s->bands);
    uint32_t in_band = (uint32_t)((uint64_t)s->k * (b + 1) / s->bands) - first;
    uint32_t y0 = s->height * b / s->bands;
    uint32_t y1 = s->height * (b + 1) / s->bands;
    uint32_t x0 = s->width * s->col / in_band;
    uint32_t x1 = s->width * (s->col + 1) / in_band;
    a->x = x0;
    a->y = y0;
    a->w = x1 - x0;
    a->h = y1 - y0;
    if (++s->col == in_band) {
        s->col = 0;
        s->band++;
    }
    return 1;
}

/* Guided self-scheduling in two shapes.  The target size t never grows
 * (pixels_left only shrinks), so neither do the areas, but by a pixel:
 *   - at a scanline start with t >= width: floor(t / width) whole
 *     scanlines;
 *   - at a scanline start with t < width: the scanline is cut into
 *     areas_pieces pieces, as equal as whole pixels allow (piece i ends
 *     at width (i + 1) / pieces); chosen only at scanline starts, so a
 *     scanline never ends on a short piece. */
static int areas_next_decreasing(struct areas *s, struct area *a)
{
    if (s->pixels_left == 0)
        return 0;
    if (s->next_x == 0) { /* a scanline's start: the target size t chooses */
        /* ceil(pixels_left / share) in 32 bits (pixels_left < 2^25): the RC
         * computes it per scanline, and a 64-bit division is a long routine. */
        uint64_t share = (uint64_t)s->factor * s->ncs;
        uint32_t t = share >= s->pixels_left ? 1u : (s->pixels_left - 1u) / (uint32_t)share + 1u;
        if (t < s->min_pixels)
            t = s->min_pixels;
        if (t >= s->width) {
            uint32_t lines = t / s->width;
            uint32_t left = s->height - s->next_y;
            if (lines > left)
                lines = left;
            a->x = 0;
            a->y = s->next_y;
            a->w = s->width;
            a->h = lines;
            s->next_y += lines;
            s->pixels_left -= lines * s->width;
            return 1;
        }
        s->pieces = areas_pieces(s, t);
        s->piece = 0;
    }
    uint32_t end = s->width * ++s->piece / s->pieces; /* < 2^24: AREAS_MAX_DIM */
    a->x = s->next_x;
    a->y = s->next_y;
    a->w = end - s->next_x;
    a->h = 1;
    s->pixels_left -= a->w;
    s->next_x = end;
    if (s->next_x == s->width) {
        s->next_x = 0;
        s->next_y++;
    }
    return 1;
}

int areas_set_guided_factor(struct areas *s, uint32_t factor)
{
    if (factor < 1 || factor > AREAS_MAX_GUIDED_FACTOR || s->handed != 0)
        return AREAS_ERR_FACTOR;
    s->factor = factor;
    return AREAS_OK;
}

int areas_next(struct areas *s, struct area *a)
{
    int got = s->mode == AREAS_DECREASING ? areas_next_decreasing(s, a)
                                          : areas_next_grid(s, a);
    s->handed += (uint32_t)got;
    if (got)
        a->y += s->y0;
    return got;
}

void areas_set_origin(struct areas *s, uint32_t y0)
{
    s->y0 = y0;
}

uint32_t areas_count(const struct areas *s)
{
    if (s->mode != AREAS_DECREASING)
        return s->k;
    /* No closed form: replay the schedule from its start. */
    struct areas replay;
    struct area a;
    uint32_t n = 0;
    if (areas_init(&replay, s->mode, s->width, s->height, s->ncs, s->k) != AREAS_OK)
        return 0;
    replay.factor = s->factor;
    while (areas_next(&replay, &a))
        n++;
    return n;
}

uint32_t areas_handed(const struct areas *s)
{
    return s->handed;
}

int areas_one_per_nc(const struct areas *s)
{
    return s->mode == AREAS_STATIC;
}

static const char *const areas_mode_names[] = {
    [AREAS_STATIC] = "static",
    [AREAS_DYNAMIC] = "dynamic",
    [AREAS_DECREASING] = "decreasing",
    [AREAS_LINES] = "lines",
};

const char *areas_mode_name(enum areas_mode mode)
{
    if ((unsigned)mode >= sizeof areas_mode_names / sizeof areas_mode_names[0])
        return "unknown";
    return areas_mode_names[mode];
}

int areas_mode_parse(const char *name, enum areas_mode *mode)
{
    for (size_t i = 0; i < sizeof areas_mode_names / sizeof areas_mode_names[0]; i++) {
        if (strcmp(name, areas_mode_names[i]) == 0) {
            *mode = (enum areas_mode)i;
            return AREAS_OK;
        }
    }
    return AREAS_ERR_MODE;
}

const char *areas_strerror(int status)
{
    switch (status) {
    case AREAS_OK:
        return "ok";
    case AREAS_ERR_MODE:
        return "unknown balancing mode (want static, dynamic, decreasing or lines)";
    case AREAS_ERR_SIZE: { /* a block: a label takes no declaration before C23 */
        _Static_assert(AREAS_MAX_DIM == 4096u, "update the message below");
        return "screen width and height must be 1..4096 (AREAS_MAX_DIM)";
    }
    case AREAS_ERR_NCS:
        return "at least one NC is needed";
    case AREAS_ERR_FACTOR: {
        _Static_assert(AREAS_MAX_GUIDED_FACTOR == 64u, "update the message below");
        return "the guided factor must be 1..64 (AREAS_MAX_GUIDED_FACTOR), set before the "
               "first area";
    }
    default:
        return "unknown areas error";
    }
}
