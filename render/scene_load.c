/* render/scene_load.c: checks a compiled scene and builds a scene_t from it
 * (see scene_load.h and proto/scene_format.h).
 *
 * Reals are checked on their binary32 bit patterns with integer compares
 * (finite, sign, range), so the check is the same, exact, in every
 * arithmetic, and the fixed build does no floating point at all.  Values
 * then enter num_t through num_from_f32_bits.
 */
#include "render/scene_load.h"

#include <stdarg.h>

#include "proto/scene_format.h"
#include "proto/textfmt.h"
#include "proto/wire.h"
#include "proto/wordsum.h"
#include "render/render.h"
#include "render/vec3.h"

#define LOAD_F32_EXP_MASK 0x7f800000u
#define LOAD_F32_SIGN 0x80000000u
#define LOAD_INLINE static inline __attribute__((always_inline))
#define LOAD_KEXP_PLAIN INT32_MIN
#define LOAD_EXP_NONE (-1000000) /* no length at all */

/* wire_get_u32 as one load where the target reads little-endian words at
 * any alignment (the board and the hosts): the compiler does not always
 * merge wire.h's four byte loads, and the loader reads every word of a
 * scene */
LOAD_INLINE uint32_t load_u32(const uint8_t *p)
{
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    uint32_t w;
    __builtin_memcpy(&w, p, sizeof w); /* a plain load: -ffreestanding would call memcpy */
    return w;
#else
    return wire_get_u32(p);
#endif
}

struct load_section {
    int present;
    uint32_t offset, count;
};

/* load_scale_bits by 2^e with the test of the common case (a normal value
 * that stays normal) worked out once for e: load_scaler_of. */
struct load_scaler {
    int e;
    uint32_t lo, span;
    uint32_t tspan; /* a triangle coordinate's common case: span, or less
                       where the scene states its triangles' extent
                       (load_scaler_of) */
};

struct load {
    const uint8_t *buf;
    uint32_t total;
    struct load_section sec[SCN_SEC_COUNT + 1]; /* by kind */
    scene_load_error_t *err;
    int unit_exp; /* world lengths enter num_t times 2^unit_exp */
    int len_exp;  /* load_len's exponent for the record at hand: unit_exp
                     plus the exponent of the cluster it lies in */
    int32_t *cexp; /* scratch, per cluster: its coordinates are stored times
                      2^(unit_exp + cexp[i]) (load_scale) */
    int32_t *kexp; /* scratch, per cluster: its keys' scales times 2^-kexp[i];
                      LOAD_KEXP_PLAIN for a plain cluster (load_cluster_plain) */
    int crc_later; /* the header alone: scene_load checks the word sum next */
    struct load_scaler scaler; /* load_scaler_at's, for scaler.e (load_prims
                                  makes the first) */
    int triangle_coords_over; /* load_scale met a triangle with a coordinate
                                 not finite or beyond SCN_MAX_COORD: each
                                 triangle's are checked one by one */
    const scene_load_known_t *known; /* what the caller knows, or NULL */
    int passed; /* known->passed: the values' checks are not made again */
    int tri_stated; /* the EXTENT section states the triangles' exponent
                       (tri_exp, LOAD_EXP_NONE: no triangle): load_scale
                       does not read the triangles, load_triangle holds
                       each one to it */
    int32_t tri_exp;
};

/* ------------------------------------------------------------ messages */

/* Sets the status and the message (cut to SCENE_LOAD_MSG_MAX - 1). */
static scene_load_status_t load_fail(struct load *L, scene_load_status_t st, const char *fmt,
                                     ...) __attribute__((format(printf, 3, 4)));
static scene_load_status_t load_fail(struct load *L, scene_load_status_t st, const char *fmt,
                                     ...)
{
    va_list ap;
    va_start(ap, fmt);
    fmt_vsnprintf(L->err->message, sizeof L->err->message, fmt, ap);
    va_end(ap);
    L->err->status = st;
    return st;
}

/* "<what><i>: <problem>" */
static scene_load_status_t load_bad(struct load *L, scene_load_status_t st, const char *what,
                                    uint32_t i, const char *problem)
{
    return load_fail(L, st, "%s%lu: %s", what, (unsigned long)i, problem);
}

/* The two limits of proto/scene_format.h, for a value out of range */
#define LOAD_LIMITS "not finite or beyond +-%ld (a length) or +-%ld (no unit)"
#define LOAD_LIMIT_ARGS (long)SCN_MAX_COORD, (long)SCN_MAX_FACTOR

/* "<what><i>: <thing> not finite or beyond ..." */
static scene_load_status_t load_range(struct load *L, const char *what, uint32_t i,
                                      const char *thing)
{
    return load_fail(L, SCENE_LOAD_ERR_VALUE, "%s%lu: %s " LOAD_LIMITS, what, (unsigned long)i,
                     thing, LOAD_LIMIT_ARGS);
}

#define LOAD_TRY(x)                                                          \
    do {                                                                     \
        scene_load_status_t st_ = (x);                                       \
        if (st_ != SCENE_LOAD_OK)                                            \
            return st_;                                                      \
    } while (0)

/* ------------------------------------------------------- reals as bits */

static uint32_t load_bits_of(float f)
{
    uint32_t u;
    /* a constant: folded, no float arithmetic; __builtin_ because the
     * firmware's -ffreestanding makes a plain memcpy a call, made for
     * every value checked */
    __builtin_memcpy(&u, &f, sizeof u);
    return u;
}

static int load_finite(uint32_t bits) { return (bits & LOAD_F32_EXP_MASK) != LOAD_F32_EXP_MASK; }

/* An unsigned key that orders finite binary32 values as the reals do;
 * -0 and +0 are the same real (the compiler writes -0 for a "-0." it
 * read, which is within 0..1). */
static uint32_t load_order_key(uint32_t bits)
{
    if (bits == LOAD_F32_SIGN)
        bits = 0;
    return (bits & LOAD_F32_SIGN) ? ~bits : bits | LOAD_F32_SIGN;
}

/* lo <= v <= hi, v finite */
static int load_in(uint32_t bits, float lo, float hi)
{
    uint32_t k = load_order_key(bits);
    return load_finite(bits) && k >= load_order_key(load_bits_of(lo)) &&
           k <= load_order_key(load_bits_of(hi));
}

/* 0 < v <= hi, v finite */
static int load_pos(uint32_t bits, float hi)
{
    return load_finite(bits) && !(bits & LOAD_F32_SIGN) && bits != 0 &&
           bits <= load_bits_of(hi);
}

static int load_zero(uint32_t bits) { return (bits & ~LOAD_F32_SIGN) == 0; }

LOAD_INLINE num_t load_num(const uint8_t *p) { return num_from_f32_bits(load_u32(p)); }

LOAD_INLINE vec3_t load_vec3(const uint8_t *p)
{
    vec3_t v = {load_num(p), load_num(p + 4), load_num(p + 8)};
    return v;
}

/* binary32 bits times 2^e, by the exponent field: exact; zeros, subnormals
 * and results under the smallest normal give a zero of the same sign */
LOAD_INLINE uint32_t load_scale_bits(uint32_t bits, int e)
{
    uint32_t field = (bits & LOAD_F32_EXP_MASK) >> 23, to = field + (uint32_t)e;
    if (field - 1u < 254u && to - 1u < 254u) /* normal to normal: the field
                                                 moves by e */
        return bits + ((uint32_t)e << 23);
    int32_t exp = (int32_t)field;
    if (exp == 0 || exp == 255)
        return exp == 0 ? (bits & LOAD_F32_SIGN) : bits;
    exp += e;
    if (exp <= 0)
        return bits & LOAD_F32_SIGN;
    if (exp >= 255) /* not reached: load_scale refuses a scene whose lengths
                       unit_exp cannot bring to 2^4 */
        return (bits & LOAD_F32_SIGN) | LOAD_F32_EXP_MASK;
    return (bits & ~LOAD_F32_EXP_MASK) | ((uint32_t)exp << 23);
}

/* The scaler of e: the exponent fields that stay normal, lo .. lo + span.
 * A triangle coordinate's common case (tspan) is held under SCN_MAX_COORD's
 * field and the extent L states, less the exponent of the cluster whose
 * coordinates are stored times 2^e: a coordinate past it takes
 * load_scale_bits and load_triangle looks at it again (load_tri_beyond). */
LOAD_INLINE struct load_scaler load_scaler_of(const struct load *L, int e)
{
    int32_t lo = e >= 0 ? 1 : 1 - e, hi = e >= 0 ? 254 - e : 254;
    struct load_scaler s = {e, (uint32_t)lo, hi >= lo ? (uint32_t)(hi - lo) : 0, 0};
    if (hi < lo)
        s.lo = 256; /* no field: every value takes load_scale_bits */
    s.tspan = s.span;
    if (L->tri_stated && s.lo != 256) {
        int32_t top = (int32_t)(load_bits_of(SCN_MAX_COORD) >> 23) - 1;
        int32_t stated = L->tri_exp == LOAD_EXP_NONE ? 0 : L->tri_exp - (e - L->unit_exp) + 127;
        top = stated < top ? stated : top;
        s.tspan = top < lo ? 0 : top - lo < (int32_t)s.span ? (uint32_t)(top - lo) : s.span;
        if (top < lo)
            s.lo = 256; /* every coordinate looked at */
    }
    return s;
}

/* load_scaler_of(L->len_exp), worked out again only when it changes (the
 * triangles of one cluster, or of plain clusters, share it). */
LOAD_INLINE struct load_scaler load_scaler_at(struct load *L)
{
    if (L->scaler.e != L->len_exp)
        L->scaler = load_scaler_of(L, L->len_exp);
    return L->scaler;
}

/* A triangle coordinate's bits scaled as load_scale_bits; *slow gathers
 * the exponent fields of those past the common case (tspan: a zero adds
 * none). */
LOAD_INLINE uint32_t load_scale_tri_bits(const struct load_scaler *s, uint32_t bits,
                                         uint32_t *slow)
{
    uint32_t field = (bits & LOAD_F32_EXP_MASK) >> 23;
    if (field - s->lo <= s->tspan) /* normal to normal, as load_scale_bits */
        return bits + ((uint32_t)s->e << 23);
    *slow |= field;
    return load_scale_bits(bits, s->e);
}

/* A length: scaled to the scene (scene_t.unit_exp) and by the power of two
 * of the cluster it lies in (L->len_exp). */
LOAD_INLINE num_t load_len(const struct load *L, const uint8_t *p)
{
    return num_from_f32_bits(load_scale_bits(load_u32(p), L->len_exp));
}

LOAD_INLINE vec3_t load_lvec3(const struct load *L, const uint8_t *p)
{
    vec3_t v = {load_len(L, p), load_len(L, p + 4), load_len(L, p + 8)};
    return v;
}

static rgb_t load_rgb(const uint8_t *p)
{
    rgb_t c = {load_num(p), load_num(p + 4), load_num(p + 8)};
    return c;
}

/* n consecutive reals at p, each within +-hi (hi > 0, finite): load_in(v,
 * -hi, hi) as one compare, since the magnitude bits of the finite values
 * order as their magnitudes do and those of an infinity or a NaN lie above
 * every finite value's */
LOAD_INLINE int load_within(const uint8_t *p, int n, float hi)
{
    uint32_t h = load_bits_of(hi);
    for (int i = 0; i < n; i++)
        if ((load_u32(p + 4 * i) & ~LOAD_F32_SIGN) > h)
            return 0;
    return 1;
}

/* n consecutive lengths at p (SCN_MAX_COORD) */
static int load_coords(const uint8_t *p, int n) { return load_within(p, n, SCN_MAX_COORD); }

/* n consecutive values without a unit at p (SCN_MAX_FACTOR) */
static int load_factors(const uint8_t *p, int n) { return load_within(p, n, SCN_MAX_FACTOR); }

static int load_units(const uint8_t *p, int n, float hi)
{
    for (int i = 0; i < n; i++)
        if (!load_in(load_u32(p + 4 * i), 0.0f, hi))
            return 0;
    return 1;
}

/* ------------------------------------------------- header and sections */

static const uint32_t load_record_size[SCN_SEC_COUNT + 1] = {
    [SCN_SEC_VIEW] = SCN_VIEW_SIZE,         [SCN_SEC_LIGHTS] = SCN_LIGHT_SIZE,
    [SCN_SEC_MATERIALS] = SCN_MAT_SIZE,     [SCN_SEC_MAPS] = SCN_MAP_SIZE,
    [SCN_SEC_TEXELS] = 1,                   [SCN_SEC_CLUSTERS] = SCN_CLUSTER_SIZE,
    [SCN_SEC_PRIMS] = SCN_PRIM_SIZE,        [SCN_SEC_COMPONENTS] = SCN_COMPONENT_SIZE,
    [SCN_SEC_KEYS] = SCN_KEY_SIZE,          [SCN_SEC_NORMALS] = SCN_NORMALS_SIZE,
    [SCN_SEC_VIEW_KEYS] = SCN_VKEY_SIZE,   [SCN_SEC_HAZE] = SCN_HAZE_SIZE,
    [SCN_SEC_EXTENT] = SCN_EXTENT_SIZE,
};

static const uint32_t load_count_limit[SCN_SEC_COUNT + 1] = {
    [SCN_SEC_VIEW] = 1,                         [SCN_SEC_LIGHTS] = SCN_MAX_LIGHTS,
    [SCN_SEC_MATERIALS] = SCN_MAX_MATERIALS,    [SCN_SEC_MAPS] = SCN_MAX_MAPS,
    [SCN_SEC_TEXELS] = SCN_MAX_TEXEL_BYTES,     [SCN_SEC_CLUSTERS] = SCN_MAX_CLUSTERS,
    [SCN_SEC_PRIMS] = SCN_MAX_PRIMS,            [SCN_SEC_COMPONENTS] = SCN_MAX_COMPONENTS,
    [SCN_SEC_KEYS] = SCN_MAX_KEYS,              [SCN_SEC_NORMALS] = SCN_MAX_PRIMS,
    [SCN_SEC_VIEW_KEYS] = SCN_MAX_VIEW_KEYS,     [SCN_SEC_HAZE] = 1,
    [SCN_SEC_EXTENT] = 1,
};

static scene_load_status_t load_header(struct load *L, size_t len)
{
    const uint8_t *b = L->buf;
    if (len < SCN_HEADER_SIZE)
        return load_fail(L, SCENE_LOAD_ERR_TRUNCATED,
                         "scene of %ld bytes is shorter than its header", (long)len);
    if (b[0] != SCN_MAGIC_0 || b[1] != SCN_MAGIC_1 || b[2] != SCN_MAGIC_2 ||
        b[3] != SCN_MAGIC_3)
        return load_fail(L, SCENE_LOAD_ERR_MAGIC, "not a compiled scene (magic is not L1SC)");
    uint16_t version = wire_get_u16(b + SCN_HDR_VERSION);
    if (version != SCN_VERSION)
        return load_fail(L, SCENE_LOAD_ERR_VERSION,
                         "format version %ld (this loader reads version %ld)", (long)version,
                         (long)SCN_VERSION);
    uint32_t total = load_u32(b + SCN_HDR_TOTAL);
    if (total > SCN_MAX_SIZE)
        return load_fail(L, SCENE_LOAD_ERR_SIZE, "total size %ld is over the limit of %ld bytes",
                         (long)total, (long)SCN_MAX_SIZE);
    if (total > len)
        return load_fail(L, SCENE_LOAD_ERR_TRUNCATED,
                         "scene truncated: header says %ld bytes, got %ld", (long)total, (long)len);
    if (total != len)
        return load_fail(L, SCENE_LOAD_ERR_SIZE, "header says %ld bytes but the scene is %ld bytes",
                         (long)total, (long)len);
    uint16_t nsec = wire_get_u16(b + SCN_HDR_SECTIONS);
    if (nsec < 1 || nsec > SCN_SEC_COUNT)
        return load_fail(L, SCENE_LOAD_ERR_SECTION, "section count %ld is not 1..%ld", (long)nsec,
                         (long)SCN_SEC_COUNT);
    uint32_t table_end = SCN_HEADER_SIZE + (uint32_t)nsec * SCN_SECENT_SIZE;
    if (table_end > total)
        return load_fail(L, SCENE_LOAD_ERR_SIZE,
                         "total size %ld cannot hold the section table of %ld entries",
                         (long)total, (long)nsec);
    L->total = total;
    if (!L->crc_later &&
        (L->known ? L->known->body_sum : wordsum(b + SCN_SUM_START, total - SCN_SUM_START)) !=
            load_u32(b + SCN_HDR_SUM))
        return load_fail(L, SCENE_LOAD_ERR_CRC, "checksum mismatch: the scene is corrupt");
    /* The table: kinds known and unique, bodies inside the file, after the
     * table, aligned, not overlapping, size = count * record size. */
    uint32_t lo[SCN_SEC_COUNT], hi[SCN_SEC_COUNT];
    for (uint32_t i = 0; i < nsec; i++) {
        const uint8_t *e = b + SCN_HEADER_SIZE + i * SCN_SECENT_SIZE;
        uint32_t kind = load_u32(e + SCN_SECENT_KIND);
        uint32_t off = load_u32(e + SCN_SECENT_OFFSET);
        uint32_t bytes = load_u32(e + SCN_SECENT_BYTES);
        uint32_t count = load_u32(e + SCN_SECENT_COUNT);
        if (kind < 1 || kind > SCN_SEC_COUNT)
            return load_fail(L, SCENE_LOAD_ERR_SECTION, "section entry %ld: unknown kind %ld",
                             (long)i, (long)kind);
        if (L->sec[kind].present)
            return load_fail(L, SCENE_LOAD_ERR_SECTION, "section kind %ld appears twice",
                             (long)kind);
        if (off % SCN_SECTION_ALIGN != 0 || off < table_end || off > total ||
            bytes > total - off)
            return load_fail(L, SCENE_LOAD_ERR_SECTION, "section kind %ld: body outside the file "
                             "(offset %ld)", (long)kind, (long)off);
        if (count > load_count_limit[kind])
            return load_fail(L, SCENE_LOAD_ERR_LIMIT, "section kind %ld: record count over its "
                             "limit of %ld", (long)kind, (long)load_count_limit[kind]);
        if ((uint64_t)count * load_record_size[kind] != bytes)
            return load_fail(L, SCENE_LOAD_ERR_SECTION, "section kind %ld: size is not count * "
                             "record size %ld", (long)kind, (long)load_record_size[kind]);
        for (uint32_t j = 0; j < i; j++)
            if (off < hi[j] && lo[j] < off + bytes)
                return load_fail(L, SCENE_LOAD_ERR_SECTION,
                                 "section kind %ld overlaps another section", (long)kind);
        lo[i] = off;
        hi[i] = off + bytes;
        L->sec[kind].present = 1;
        L->sec[kind].offset = off;
        L->sec[kind].count = count;
    }
    if (!L->sec[SCN_SEC_VIEW].present || L->sec[SCN_SEC_VIEW].count != 1)
        return load_fail(L, SCENE_LOAD_ERR_MISSING, "the view section is missing");
    if (!L->sec[SCN_SEC_CLUSTERS].present || L->sec[SCN_SEC_CLUSTERS].count < 1)
        return load_fail(L, SCENE_LOAD_ERR_MISSING, "the cluster section (root) is missing");
    return SCENE_LOAD_OK;
}

static const uint8_t *load_rec(const struct load *L, int kind, uint32_t i)
{
    return L->buf + L->sec[kind].offset + i * load_record_size[kind];
}

/* ------------------------------------------------------------ records */

/* A camera: eye, look_at and up as consecutive vectors at p (the VIEW
 * record's and a camera key's order), the tangent at tan; what names it
 * in a message. */
_Static_assert(SCN_VIEW_LOOK_AT == SCN_VIEW_EYE + 12 && SCN_VIEW_UP == SCN_VIEW_EYE + 24 &&
               SCN_VKEY_LOOK_AT == SCN_VKEY_EYE + 12 && SCN_VKEY_UP == SCN_VKEY_EYE + 24,
               "a camera's vectors follow one another");
static scene_load_status_t load_camera(struct load *L, const uint8_t *p, const uint8_t *tan,
                                       const char *what, scene_camera_t *c)
{
    if (!load_coords(p, 6) || !load_factors(p + 24, 3))
        return load_fail(L, SCENE_LOAD_ERR_VALUE, "%s: a coordinate is " LOAD_LIMITS, what,
                         LOAD_LIMIT_ARGS);
    if (!load_pos(load_u32(tan), SCN_MAX_TAN_HALF_FOV))
        return load_fail(L, SCENE_LOAD_ERR_VALUE, "%s: field of view out of range", what);
    c->eye = load_lvec3(L, p);
    c->look_at = load_lvec3(L, p + 12);
    c->up = load_vec3(p + 24);
    c->tan_half_fov_y = load_num(tan);
    return SCENE_LOAD_OK;
}

/* The VIEW record's anti-aliasing fields: depth 0..SCN_MAX_AA_DEPTH, the
 * word after it 0, the threshold 0..1. */
static scene_load_status_t load_aa(struct load *L, const uint8_t *p, scene_t *s)
{
    uint16_t depth = wire_get_u16(p + SCN_VIEW_AA_DEPTH);
    if (depth > SCN_MAX_AA_DEPTH)
        return load_fail(L, SCENE_LOAD_ERR_LIMIT, "aa depth %ld not 0..%ld", (long)depth,
                         (long)SCN_MAX_AA_DEPTH);
    if (wire_get_u16(p + SCN_VIEW_AA_ZERO) != 0)
        return load_fail(L, SCENE_LOAD_ERR_VALUE, "the view's reserved word after aa depth "
                         "is not 0");
    if (!load_units(p + SCN_VIEW_AA_THRESHOLD, 1, 1.0f))
        return load_fail(L, SCENE_LOAD_ERR_VALUE, "aa_threshold not within 0..1");
    s->options.antialias = (wire_get_u16(p + SCN_VIEW_FLAGS) & SCN_OPT_ANTIALIAS) != 0;
    s->options.aa_depth = (uint8_t)depth;
    s->options.aa_threshold = load_num(p + SCN_VIEW_AA_THRESHOLD);
    return SCENE_LOAD_OK;
}

static scene_load_status_t load_view(struct load *L, scene_t *s)
{
    const uint8_t *p = load_rec(L, SCN_SEC_VIEW, 0);
    uint16_t w = wire_get_u16(p + SCN_VIEW_WIDTH), h = wire_get_u16(p + SCN_VIEW_HEIGHT);
    uint16_t depth = wire_get_u16(p + SCN_VIEW_MAX_DEPTH);
    uint16_t flags = wire_get_u16(p + SCN_VIEW_FLAGS);
    uint32_t frames = load_u32(p + SCN_VIEW_FRAMES);
    uint32_t steps = load_u32(p + SCN_VIEW_DENSITY_STEPS);
    if (w < 1 || w > SCN_MAX_WIDTH || h < 1 || h > SCN_MAX_HEIGHT)
        return load_fail(L, SCENE_LOAD_ERR_LIMIT, "image size %ldx%ld outside 1..1024 per side",
                         (long)w, (long)h);
    if (depth > SCN_MAX_DEPTH)
        return load_fail(L, SCENE_LOAD_ERR_LIMIT, "max depth %ld over the limit of %ld",
                         (long)depth, (long)SCN_MAX_DEPTH);
    if (flags & ~SCN_OPT_KNOWN)
        return load_fail(L, SCENE_LOAD_ERR_VALUE, "unknown option flags %ld", (long)flags);
    if (frames < 1 || frames > SCN_MAX_FRAMES)
        return load_fail(L, SCENE_LOAD_ERR_LIMIT, "frame count %ld not 1..%ld", (long)frames,
                         (long)SCN_MAX_FRAMES);
    LOAD_TRY(load_camera(L, p + SCN_VIEW_EYE, p + SCN_VIEW_TAN_HALF_FOV_Y, "camera",
                         &s->camera));
    if (!load_units(p + SCN_VIEW_BACKGROUND, 3, 1.0f))
        return load_fail(L, SCENE_LOAD_ERR_VALUE, "background colour not within 0..1");
    if (!load_units(p + SCN_VIEW_MIN_WEIGHT, 1, 1.0f))
        return load_fail(L, SCENE_LOAD_ERR_VALUE, "min_weight not within 0..1");
    if (steps < SCN_MIN_DENSITY_STEPS || steps > SCN_MAX_DENSITY_STEPS)
        return load_fail(L, SCENE_LOAD_ERR_LIMIT, "density_steps %lu not %ld..%ld",
                         (unsigned long)steps, (long)SCN_MIN_DENSITY_STEPS,
                         (long)SCN_MAX_DENSITY_STEPS);
    LOAD_TRY(load_aa(L, p, s));
    s->width = w;
    s->height = h;
    s->frame_count = frames;
    s->background = load_rgb(p + SCN_VIEW_BACKGROUND);
    s->options.max_depth = (uint8_t)depth;
    s->options.min_weight = load_num(p + SCN_VIEW_MIN_WEIGHT);
    s->options.density_steps = (uint16_t)steps;
    s->options.refractionless = (flags & SCN_OPT_REFRACTIONLESS) != 0;
    s->options.use_bounds = (flags & SCN_OPT_NO_BOUNDS) == 0;
    s->options.use_hierarchy = (flags & SCN_OPT_NO_HIERARCHY) == 0;
    s->options.shadows = (flags & SCN_OPT_NO_SHADOWS) == 0;
    s->options.refraction = (flags & SCN_OPT_NO_REFRACTION) == 0;
    s->options.mark_lost = (flags & SCN_OPT_MARK_LOST) != 0;
    s->options.check_lost = (flags & SCN_OPT_CHECK_LOST) != 0;
    s->options.world_space = (flags & SCN_OPT_WORLD_SPACE) != 0;
    s->options.ambient_shadowed = (flags & SCN_OPT_AMBIENT_SHADOWED) != 0;
    s->options.shadow_tint = (flags & SCN_OPT_UNTINTED_SHADOWS) == 0;
    s->options.spd_rules = (flags & SCN_OPT_SPD_RULES) != 0;
    /* eye == look_at and up parallel to the view are refused by
     * render_prepare (RENDER_ERR_CAMERA), which does that geometry anyway. */
    return SCENE_LOAD_OK;
}

/* A light's values of kind kind (SCN_LIGHT_*): colour, position,
 * direction, cos_inner, cos_outer at p in that order (the LIGHTS record's
 * and a light key's); what and i name it in a message. */
_Static_assert(SCN_LIGHT_POSITION - SCN_LIGHT_COLOUR == SCN_VKEY_POSITION - SCN_VKEY_COLOUR &&
               SCN_LIGHT_DIRECTION - SCN_LIGHT_COLOUR == SCN_VKEY_DIRECTION - SCN_VKEY_COLOUR &&
               SCN_LIGHT_COS_INNER - SCN_LIGHT_COLOUR == SCN_VKEY_COS_INNER - SCN_VKEY_COLOUR &&
               SCN_LIGHT_COS_OUTER - SCN_LIGHT_COLOUR == SCN_VKEY_COS_OUTER - SCN_VKEY_COLOUR,
               "a light's values lie alike in its record and its keys");
#define LOAD_LIGHT_AT(field) (p + (SCN_LIGHT_##field - SCN_LIGHT_COLOUR))
static scene_load_status_t load_light_values(struct load *L, const uint8_t *p, uint32_t kind,
                                             const char *what, uint32_t i, scene_light_t *l)
{
    if (!load_units(LOAD_LIGHT_AT(COLOUR), 3, SCN_MAX_INTENSITY))
        return load_bad(L, SCENE_LOAD_ERR_VALUE, what, i, "colour out of range");
    if (!load_coords(LOAD_LIGHT_AT(POSITION), 3) || !load_factors(LOAD_LIGHT_AT(DIRECTION), 3))
        return load_range(L, what, i, "position or direction");
    const uint8_t *d = LOAD_LIGHT_AT(DIRECTION);
    if (kind != SCN_LIGHT_POINT && load_zero(load_u32(d)) &&
        load_zero(load_u32(d + 4)) && load_zero(load_u32(d + 8)))
        return load_bad(L, SCENE_LOAD_ERR_VALUE, what, i, "direction is zero");
    uint32_t ci = load_u32(LOAD_LIGHT_AT(COS_INNER));
    uint32_t co = load_u32(LOAD_LIGHT_AT(COS_OUTER));
    if (!load_in(ci, -1.0f, 1.0f) || !load_in(co, -1.0f, 1.0f) ||
        (kind == SCN_LIGHT_SPOT && load_order_key(co) >= load_order_key(ci)))
        return load_bad(L, SCENE_LOAD_ERR_VALUE, what, i,
                        "cone cosines not -1..1 with outer < inner");
    l->kind = kind == SCN_LIGHT_PARALLEL ? SCENE_LIGHT_PARALLEL
              : kind == SCN_LIGHT_POINT  ? SCENE_LIGHT_POINT
                                         : SCENE_LIGHT_SPOT;
    l->intensity = load_rgb(LOAD_LIGHT_AT(COLOUR));
    l->position = load_lvec3(L, LOAD_LIGHT_AT(POSITION));
    l->direction = load_vec3(d);
    l->cos_inner = num_from_f32_bits(ci);
    l->cos_outer = num_from_f32_bits(co);
    return SCENE_LOAD_OK;
}
#undef LOAD_LIGHT_AT

/* The haze, when the scene has one: its colour, and 1/D in the scene's
 * stored units (times 2^-unit_exp, exact), within SCN_MAX_FACTOR. */
static scene_load_status_t load_haze(struct load *L, scene_t *s)
{
    s->haze = 0;
    if (!L->sec[SCN_SEC_HAZE].present || L->sec[SCN_SEC_HAZE].count == 0)
        return SCENE_LOAD_OK;
    const uint8_t *p = load_rec(L, SCN_SEC_HAZE, 0);
    uint32_t inv = wire_get_u32(p + SCN_HAZE_INV_DISTANCE);
    if (!load_units(p + SCN_HAZE_COLOUR, 3, 1.0f))
        return load_fail(L, SCENE_LOAD_ERR_VALUE, "haze colour not within 0..1");
    if (!load_pos(inv, 1.0e30f))
        return load_fail(L, SCENE_LOAD_ERR_VALUE, "haze 1/distance not a positive number");
    num_t k = num_from_f32_bits(load_scale_bits(inv, -L->unit_exp));
    if (num_is_sat(k) || num_gt(k, NUM_C(SCN_MAX_FACTOR)))
        return load_fail(L, SCENE_LOAD_ERR_VALUE, "haze distance under 1/%ld of the scene's "
                         "scaled unit (its largest length is scaled to 8..16): the haze "
                         "would hide everything", (long)SCN_MAX_FACTOR);
    s->haze = 1;
    s->haze_colour = load_rgb(p + SCN_HAZE_COLOUR);
    s->haze_k = k;
    return SCENE_LOAD_OK;
}

/* The keys of the camera and the lights: grouped by target (the camera's,
 * then by rising light index), frames rising within a target, each
 * checked as the record it stands for. */
static scene_load_status_t load_view_keys(struct load *L, scene_view_key_t *out)
{
    uint32_t n = L->sec[SCN_SEC_VIEW_KEYS].present ? L->sec[SCN_SEC_VIEW_KEYS].count : 0;
    uint32_t n_light = L->sec[SCN_SEC_LIGHTS].present ? L->sec[SCN_SEC_LIGHTS].count : 0;
    uint32_t rank_before = 0, frame_before = 0; /* rank: 1 the camera, 2 + i light i */
    for (uint32_t i = 0; i < n; i++) {
        const uint8_t *p = load_rec(L, SCN_SEC_VIEW_KEYS, i);
        uint32_t frame = load_u32(p + SCN_VKEY_FRAME);
        uint32_t target = load_u32(p + SCN_VKEY_TARGET);
        if (target != SCN_VKEY_CAMERA && target >= n_light)
            return load_bad(L, SCENE_LOAD_ERR_INDEX, "view key ", i,
                            "names neither the camera nor a light");
        uint32_t rank = target == SCN_VKEY_CAMERA ? 1 : 2 + target;
        if (frame >= SCN_MAX_FRAMES)
            return load_bad(L, SCENE_LOAD_ERR_LIMIT, "view key ", i,
                            "frame over SCN_MAX_FRAMES - 1");
        if (rank < rank_before || (rank == rank_before && frame <= frame_before))
            return load_bad(L, SCENE_LOAD_ERR_TREE, "view key ", i,
                            "out of order (the camera's keys, then each light's by index, "
                            "frames rising)");
        rank_before = rank;
        frame_before = frame;
        scene_view_key_t *k = &out[i];
        k->frame = frame;
        if (target == SCN_VKEY_CAMERA) {
            if (load_u32(p + SCN_VKEY_RESERVED) != 0)
                return load_bad(L, SCENE_LOAD_ERR_VALUE, "view key ", i,
                                "reserved field not zero");
            k->target = SCENE_VIEW_KEY_CAMERA;
            LOAD_TRY(load_camera(L, p + SCN_VKEY_EYE, p + SCN_VKEY_TAN_HALF_FOV_Y,
                                 "camera key", &k->v.camera));
        } else {
            k->target = (uint16_t)target;
            uint32_t kind = load_u32(load_rec(L, SCN_SEC_LIGHTS, target) + SCN_LIGHT_KIND);
            LOAD_TRY(load_light_values(L, p + SCN_VKEY_COLOUR, kind, "light key ", i,
                                       &k->v.light));
        }
    }
    return SCENE_LOAD_OK;
}

static scene_load_status_t load_lights(struct load *L, scene_light_t *out)
{
    for (uint32_t i = 0; i < L->sec[SCN_SEC_LIGHTS].count; i++) {
        const uint8_t *p = load_rec(L, SCN_SEC_LIGHTS, i);
        uint32_t kind = load_u32(p + SCN_LIGHT_KIND);
        if (kind < SCN_LIGHT_PARALLEL || kind > SCN_LIGHT_SPOT)
            return load_bad(L, SCENE_LOAD_ERR_VALUE, "light ", i, "unknown kind");
        LOAD_TRY(load_light_values(L, p + SCN_LIGHT_COLOUR, kind, "light ", i, &out[i]));
    }
    return SCENE_LOAD_OK;
}

/* The loader's kind of a map record's kind, or -1 when unknown. */
static int load_map_kind(uint16_t kind)
{
    switch (kind) {
    case SCN_MAP_COLOUR: return SCENE_MAP_COLOUR;
    case SCN_MAP_BUMP: return SCENE_MAP_BUMP;
    case SCN_MAP_NORMAL: return SCENE_MAP_NORMAL;
    case SCN_MAP_ATTRIBUTE: return SCENE_MAP_ATTRIBUTE;
    default: return -1;
    }
}

static scene_load_status_t load_maps(struct load *L, scene_map_t *out, uint8_t *texels)
{
    uint32_t n_texels = L->sec[SCN_SEC_TEXELS].present ? L->sec[SCN_SEC_TEXELS].count : 0;
    const uint8_t *src = L->sec[SCN_SEC_TEXELS].present ? load_rec(L, SCN_SEC_TEXELS, 0) : 0;
    for (uint32_t i = 0; i < L->sec[SCN_SEC_MAPS].count; i++) {
        const uint8_t *p = load_rec(L, SCN_SEC_MAPS, i);
        int kind = load_map_kind(wire_get_u16(p + SCN_MAP_KIND));
        uint16_t w = wire_get_u16(p + SCN_MAP_WIDTH), h = wire_get_u16(p + SCN_MAP_HEIGHT);
        uint32_t first = load_u32(p + SCN_MAP_FIRST);
        if (kind < 0)
            return load_bad(L, SCENE_LOAD_ERR_VALUE, "map ", i, "unknown kind");
        if (wire_get_u16(p + SCN_MAP_RESERVED) != 0)
            return load_bad(L, SCENE_LOAD_ERR_VALUE, "map ", i, "reserved field not zero");
        if (w < 1 || w > SCN_MAX_MAP_SIDE || h < 1 || h > SCN_MAX_MAP_SIDE)
            return load_bad(L, SCENE_LOAD_ERR_LIMIT, "map ", i, "size outside 1..1024");
        uint32_t bytes = (uint32_t)w * h * scene_map_texel_bytes((uint8_t)kind);
        if (first > n_texels || bytes > n_texels - first)
            return load_bad(L, SCENE_LOAD_ERR_INDEX, "map ", i,
                            "texels outside the texel section");
        if (!load_pos(load_u32(p + SCN_MAP_REPEAT_U), SCN_MAX_REPEAT) ||
            !load_pos(load_u32(p + SCN_MAP_REPEAT_V), SCN_MAX_REPEAT))
            return load_bad(L, SCENE_LOAD_ERR_VALUE, "map ", i, "repeat not > 0 and finite");
        if (!load_in(load_u32(p + SCN_MAP_BUMP_DEPTH), 0.0f, SCN_MAX_FACTOR))
            return load_bad(L, SCENE_LOAD_ERR_VALUE, "map ", i, "bump depth out of range");
        /* a normal map's z (along N) is at least 1: every texel's normal
         * has a length normalize can take, and faces out of the surface */
        if (kind == SCENE_MAP_NORMAL)
            for (uint32_t t = 0; t < (uint32_t)w * h; t++)
                if ((int8_t)src[first + 3 * t + 2] < 1)
                    return load_bad(L, SCENE_LOAD_ERR_VALUE, "map ", i,
                                    "normal map texel with z < 1 (not out of the surface)");
        scene_map_t *m = &out[i];
        m->kind = (uint8_t)kind;
        m->width = w;
        m->height = h;
        m->texels = texels + first;
        m->repeat_u = load_num(p + SCN_MAP_REPEAT_U);
        m->repeat_v = load_num(p + SCN_MAP_REPEAT_V);
        m->bump_depth = load_num(p + SCN_MAP_BUMP_DEPTH);
    }
    if (n_texels)
        memcpy(texels, src, n_texels);
    return SCENE_LOAD_OK;
}

/* A material's map index at off: *out its index or SCENE_NONE; 0 when it
 * names no map of that kind. */
static int load_map_index(struct load *L, const scene_map_t *maps, const uint8_t *p,
                          unsigned off, uint8_t kind, uint16_t *out)
{
    uint16_t i = wire_get_u16(p + off);
    *out = i == SCN_NO_INDEX ? SCENE_NONE : i;
    return i == SCN_NO_INDEX || (i < L->sec[SCN_SEC_MAPS].count && maps[i].kind == kind);
}

static scene_load_status_t load_materials(struct load *L, const scene_map_t *maps,
                                          scene_material_t *out)
{
    for (uint32_t i = 0; i < L->sec[SCN_SEC_MATERIALS].count; i++) {
        const uint8_t *p = load_rec(L, SCN_SEC_MATERIALS, i);
        if (!load_units(p + SCN_MAT_COLOUR, 8, 1.0f))
            return load_bad(L, SCENE_LOAD_ERR_VALUE, "material ", i,
                            "colour, dic, drc, src, trc or fresnel not within 0..1");
        if (!load_in(load_u32(p + SCN_MAT_IOR), 1.0f, SCN_MAX_IOR))
            return load_bad(L, SCENE_LOAD_ERR_VALUE, "material ", i, "ior not within 1..10");
        uint16_t phong = wire_get_u16(p + SCN_MAT_PHONG);
        if (phong > SCN_MAX_PHONG)
            return load_bad(L, SCENE_LOAD_ERR_LIMIT, "material ", i, "phong n over 1024");
        scene_material_t *m = &out[i];
        if (!load_map_index(L, maps, p, SCN_MAT_COLOUR_MAP, SCENE_MAP_COLOUR, &m->colour_map))
            return load_bad(L, SCENE_LOAD_ERR_INDEX, "material ", i,
                            "colour map index out of range or not a colour map");
        if (!load_map_index(L, maps, p, SCN_MAT_BUMP_MAP, SCENE_MAP_BUMP, &m->bump_map))
            return load_bad(L, SCENE_LOAD_ERR_INDEX, "material ", i,
                            "bump map index out of range or not a bump map");
        if (!load_map_index(L, maps, p, SCN_MAT_NORMAL_MAP, SCENE_MAP_NORMAL, &m->normal_map))
            return load_bad(L, SCENE_LOAD_ERR_INDEX, "material ", i,
                            "normal map index out of range or not a normal map");
        if (m->bump_map != SCENE_NONE && m->normal_map != SCENE_NONE)
            return load_bad(L, SCENE_LOAD_ERR_VALUE, "material ", i,
                            "both a bump map and a normal map");
        if (!load_map_index(L, maps, p, SCN_MAT_DIC_MAP, SCENE_MAP_ATTRIBUTE, &m->dic_map) ||
            !load_map_index(L, maps, p, SCN_MAT_DRC_MAP, SCENE_MAP_ATTRIBUTE, &m->drc_map) ||
            !load_map_index(L, maps, p, SCN_MAT_SRC_MAP, SCENE_MAP_ATTRIBUTE, &m->src_map) ||
            !load_map_index(L, maps, p, SCN_MAT_TRC_MAP, SCENE_MAP_ATTRIBUTE, &m->trc_map))
            return load_bad(L, SCENE_LOAD_ERR_INDEX, "material ", i,
                            "dic, drc, src or trc map index out of range or not an attribute map");
        m->colour = load_rgb(p + SCN_MAT_COLOUR);
        m->dic = load_num(p + SCN_MAT_DIC);
        m->drc = load_num(p + SCN_MAT_DRC);
        m->src = load_num(p + SCN_MAT_SRC);
        m->trc = load_num(p + SCN_MAT_TRC);
        m->fresnel = load_num(p + SCN_MAT_FRESNEL);
        m->ior = load_num(p + SCN_MAT_IOR);
        m->phong_n = phong;
        if (num_gt(num_add(m->src, m->trc), num_add(NUM_ONE, NUM_C(0.001))))
            return load_bad(L, SCENE_LOAD_ERR_VALUE, "material ", i, "src + trc over 1");
    }
    return SCENE_LOAD_OK;
}

static scene_load_status_t load_keys(struct load *L, scene_key_t *out)
{
    L->len_exp = L->unit_exp; /* a cluster's keys: again in load_clusters */
    for (uint32_t i = 0; i < L->sec[SCN_SEC_KEYS].count; i++) {
        const uint8_t *p = load_rec(L, SCN_SEC_KEYS, i);
        if (!load_coords(p + SCN_KEY_TRANSLATE, 3) ||
            !load_within(p + SCN_KEY_SCALE, 3, SCN_MAX_SCALE))
            return load_range(L, "key ", i, "translation or scale");
        if (load_u32(p + SCN_KEY_FRAME) >= SCN_MAX_FRAMES)
            return load_bad(L, SCENE_LOAD_ERR_LIMIT, "key ", i, "frame number over the limit");
        for (int k = 0; k < 4; k++)
            if (!load_in(load_u32(p + SCN_KEY_ROTATION + 4 * k), -1.0f, 1.0f))
                return load_bad(L, SCENE_LOAD_ERR_VALUE, "key ", i,
                                "quaternion component not within -1..1");
        for (int k = 0; k < 3; k++)
            if (load_zero(load_u32(p + SCN_KEY_SCALE + 4 * k)))
                return load_bad(L, SCENE_LOAD_ERR_VALUE, "key ", i, "scale is zero");
        scene_key_t *k = &out[i];
        k->frame = load_u32(p + SCN_KEY_FRAME);
        k->translate = load_lvec3(L, p + SCN_KEY_TRANSLATE);
        k->rot_w = load_num(p + SCN_KEY_ROTATION);
        k->rot_x = load_num(p + SCN_KEY_ROTATION + 4);
        k->rot_y = load_num(p + SCN_KEY_ROTATION + 8);
        k->rot_z = load_num(p + SCN_KEY_ROTATION + 12);
        k->scale = load_vec3(p + SCN_KEY_SCALE);
        num_t norm2 = num_add(num_dot3(k->rot_w, k->rot_x, k->rot_y, k->rot_w, k->rot_x,
                                       k->rot_y),
                              num_mul(k->rot_z, k->rot_z));
        num_t tol = NUM_C(2 * SCN_QUAT_NORM_TOLERANCE);
        if (num_lt(norm2, num_sub(NUM_ONE, tol)) || num_gt(norm2, num_add(NUM_ONE, tol)))
            return load_bad(L, SCENE_LOAD_ERR_VALUE, "key ", i,
                            "rotation is not a unit quaternion");
    }
    return SCENE_LOAD_OK;
}

/* The identity, the static matrix of the clusters the compiler's bounding
 * hierarchy makes: rows of the 3x4 matrix as binary32 bits. */
static const uint32_t load_identity_bits[12] = {
    0x3f800000u, 0, 0, 0, 0, 0x3f800000u, 0, 0, 0, 0, 0x3f800000u, 0,
};

/* A cluster without keys whose static matrix is the identity, bit for bit:
 * what load_scale and load_clusters make of it follows without their
 * checks and scalings (no keys, cexp its parent's, the identity again);
 * load_scale marks it in kexp for load_clusters. */
static int load_cluster_plain(const uint8_t *p)
{
    uint32_t d = load_u32(p + SCN_CLUSTER_KEY_COUNT);
#pragma GCC unroll 12
    for (int k = 0; k < 12; k++) /* one load, xor and or a word */
        d |= load_u32(p + SCN_CLUSTER_MATRIX + 4 * k) ^ load_identity_bits[k];
    return d == 0;
}

/* Cluster i's (record p, parent's exponent cp) matrix checked, and its
 * keys and matrix scaled (load_scale) into keys and c. */
static scene_load_status_t load_cluster_values(struct load *L, uint32_t i, const uint8_t *p,
                                               int32_t cp, scene_key_t *keys,
                                               scene_cluster_t *c)
{
    for (int k = 0; k < 12; k++)
        if (!load_within(p + SCN_CLUSTER_MATRIX + 4 * k, 1,
                         k % 4 == 3 ? SCN_MAX_COORD : SCN_MAX_SCALE))
            return load_range(L, "cluster ", i, "a matrix entry");
    /* K(f) * M maps the cluster's coordinates (times 2^cexp[i]) to its
     * parent's (times 2^cp): K's translations are the parent's lengths,
     * its scales lose kexp, M's translations are lengths between K and
     * M (2^(cp + kexp)), M's 3x3 part loses the rest (load_scale) */
    int32_t mexp = L->cexp[i] - cp - L->kexp[i];
    for (uint32_t k = c->first_key; k < c->first_key + c->key_count; k++) {
        const uint8_t *kp = load_rec(L, SCN_SEC_KEYS, k);
        L->len_exp = L->unit_exp + (int)cp;
        keys[k].translate = load_lvec3(L, kp + SCN_KEY_TRANSLATE);
        for (int a = 0; a < 3; a++) {
            num_t v = num_from_f32_bits(load_scale_bits(
                load_u32(kp + SCN_KEY_SCALE + 4 * a), -(int)L->kexp[i]));
            *(a == 0 ? &keys[k].scale.x : a == 1 ? &keys[k].scale.y : &keys[k].scale.z) = v;
        }
    }
    L->len_exp = L->unit_exp + (int)(cp + L->kexp[i]);
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 4; k++)
            c->local.m[r][k] =
                k == 3 ? load_len(L, p + SCN_CLUSTER_MATRIX + 4 * (r * 4 + k))
                       : num_from_f32_bits(load_scale_bits(
                             load_u32(p + SCN_CLUSTER_MATRIX + 4 * (r * 4 + k)),
                             -(int)mexp));
    return SCENE_LOAD_OK;
}

/* *to = *from, a row at a time: as a whole, the wide copy's (96 bytes)
 * would be the C library's copy, a byte at a time. */
static inline void load_copy_xform(xform_t *to, const xform_t *from)
{
#pragma GCC unroll 3
    for (int r = 0; r < 3; r++) {
        num_t a = from->m[r][0], b = from->m[r][1], c = from->m[r][2], d = from->m[r][3];
        to->m[r][0] = a, to->m[r][1] = b, to->m[r][2] = c, to->m[r][3] = d;
    }
}

/* Parents come before children, nesting is bounded, key ranges are inside
 * the key section and their frames rise: the tree is acyclic by the first
 * rule alone. */
static scene_load_status_t load_clusters(struct load *L, scene_key_t *keys,
                                         scene_cluster_t *out, uint8_t *nesting)
{
    uint32_t n_keys = L->sec[SCN_SEC_KEYS].present ? L->sec[SCN_SEC_KEYS].count : 0;
    xform_t identity; /* what load_cluster_values makes of a plain cluster */
    for (int k = 0; k < 12; k++)
        identity.m[k / 4][k % 4] = num_from_f32_bits(load_identity_bits[k]);
    const uint8_t *rec = load_rec(L, SCN_SEC_CLUSTERS, 0);
    for (uint32_t i = 0, n = L->sec[SCN_SEC_CLUSTERS].count; i < n; i++) {
        const uint8_t *p = rec + (size_t)i * SCN_CLUSTER_SIZE;
        uint32_t parent = load_u32(p + SCN_CLUSTER_PARENT);
        uint32_t kc = load_u32(p + SCN_CLUSTER_KEY_COUNT);
        uint32_t kf = load_u32(p + SCN_CLUSTER_KEY_FIRST);
        if (i == 0 ? parent != SCN_NO_CLUSTER : parent >= i)
            return load_bad(L, SCENE_LOAD_ERR_TREE, "cluster ", i,
                            i == 0 ? "the root has a parent"
                                   : "parent index not below its own (cycle or forward link)");
        nesting[i] = i == 0 ? 0 : (uint8_t)(nesting[parent] + 1);
        if (nesting[i] > SCN_MAX_CLUSTER_NESTING)
            return load_bad(L, SCENE_LOAD_ERR_TREE, "cluster ", i, "nested deeper than 32");
        if (kf > n_keys || kc > n_keys - kf || kc > SCN_MAX_CLUSTER_KEYS)
            return load_bad(L, SCENE_LOAD_ERR_INDEX, "cluster ", i,
                            "key range outside the key section");
        for (uint32_t k = 1; k < kc; k++)
            if (keys[kf + k].frame <= keys[kf + k - 1].frame)
                return load_bad(L, SCENE_LOAD_ERR_TREE, "cluster ", i,
                                "key frames do not rise");
        scene_cluster_t *c = &out[i];
        c->parent = i == 0 ? SCENE_NO_CLUSTER : parent;
        c->first_key = kf;
        c->key_count = kc;
        if (L->kexp[i] == LOAD_KEXP_PLAIN)
            load_copy_xform(&c->local, &identity);
        else
            LOAD_TRY(load_cluster_values(L, i, p, i == 0 ? 0 : L->cexp[parent], keys, c));
    }
    return SCENE_LOAD_OK;
}

static scene_load_status_t load_components(struct load *L, scene_density_component_t *out)
{
    uint32_t n = L->sec[SCN_SEC_COMPONENTS].present ? L->sec[SCN_SEC_COMPONENTS].count : 0;
    L->len_exp = L->unit_exp; /* a density sphere's: again in load_prims */
    for (uint32_t i = 0; i < n; i++) {
        const uint8_t *p = load_rec(L, SCN_SEC_COMPONENTS, i);
        uint32_t weight = load_u32(p + SCN_COMPONENT_WEIGHT);
        if (!load_coords(p + SCN_COMPONENT_CENTRE, 3) ||
            !load_pos(load_u32(p + SCN_COMPONENT_RADIUS), SCN_MAX_COORD) ||
            !load_factors(p + SCN_COMPONENT_WEIGHT, 1) || load_zero(weight))
            return load_bad(L, SCENE_LOAD_ERR_VALUE, "density component ", i,
                            "centre, radius (> 0) or weight (non-zero) out of range");
        out[i].centre = load_lvec3(L, p + SCN_COMPONENT_CENTRE);
        out[i].radius = load_len(L, p + SCN_COMPONENT_RADIUS);
        out[i].weight = num_from_f32_bits(weight);
    }
    return SCENE_LOAD_OK;
}

/* A triangle with a height under SCN_LOAD_MIN_TRIANGLE_HEIGHT: the
 * renderer divides by its heights.  With s the sine of the angle at v0,
 * the heights over the edges at v0 are |e2| s and |e1| s, and the third is
 * at least half the smaller of them: the smaller is |e1 x e2| / max(|e1|,
 * |e2|).  In fixed point unit vectors keep every product within range; in
 * IEEE arithmetic it is compared squared, without a root or a division. */
static int load_sliver(const vec3_t v[3], int unit_exp)
{
    vec3_t e1 = vec3_sub(v[1], v[0]), e2 = vec3_sub(v[2], v[0]);
    num_t least = num_scale2(NUM_C(SCN_LOAD_MIN_TRIANGLE_HEIGHT), unit_exp);
#if defined(LINKS1_NUM_FIXED)
    vec3_t u1 = vec3_normalize(e1), u2 = vec3_normalize(e2);
    num_t l1 = vec3_dot(e1, u1), l2 = vec3_dot(e2, u2);
    num_t sine = vec3_length(vec3_cross(u1, u2));
    num_t h = num_mul(num_lt(l1, l2) ? l1 : l2, sine);
    return num_lt(h, least);
#else
    vec3_t c = vec3_cross(e1, e2);
    num_t longer = num_max(vec3_dot(e1, e1), vec3_dot(e2, e2));
    return !num_gt(longer, NUM_ZERO) ||
           num_lt(vec3_dot(c, c), num_mul(num_mul(least, least), longer));
#endif
}

/* Triangle i's coordinates (values v), some past its scaler's common case
 * where the scene states the triangles' extent: refused when one is not
 * finite or beyond SCN_MAX_COORD, or beyond the extent stated. */
static __attribute__((noinline, cold)) scene_load_status_t load_tri_beyond(struct load *L, uint32_t i, const uint8_t *v)
{
    for (int k = 0; k < 9; k++) {
        uint32_t bits = load_u32(v + 4 * k) & ~LOAD_F32_SIGN;
        int32_t field = (int32_t)(bits >> 23);
        if (bits > load_bits_of(SCN_MAX_COORD))
            return load_range(L, "prim ", i, "a value is");
        if (field != 0 && (L->tri_exp == LOAD_EXP_NONE ||
                           field - 127 + (L->len_exp - L->unit_exp) > L->tri_exp))
            return load_bad(L, SCENE_LOAD_ERR_VALUE, "prim ", i,
                            "a coordinate beyond the triangles' extent the scene states "
                            "(its EXTENT section)");
    }
    return SCENE_LOAD_OK;
}

/* A triangle record whose material, cluster and component range are
 * right: its 15 values checked (9 lengths, 6 texture coordinates; not when
 * passed, scene_load_known_t's) and loaded into o as load_prims's general
 * path does, with its refusals. */
_Static_assert(SCN_TRIANGLE_VALUES == 15 && SCN_PRIM_MAX_VALUES == 15,
               "a triangle uses every value of its record");
LOAD_INLINE scene_load_status_t load_triangle(struct load *L, uint32_t i, const uint8_t *v,
                                              scene_prim_t *o, const int passed)
{
    uint32_t over = 0, tex[6];
    if (L->triangle_coords_over) /* else load_scale found every one in range */
        for (int k = 0; k < 9; k++)
            over |= (load_u32(v + 4 * k) & ~LOAD_F32_SIGN) > load_bits_of(SCN_MAX_COORD);
#pragma GCC unroll 6
    for (int k = 0; k < 6; k++) { /* read once: checked, then loaded */
        tex[k] = load_u32(v + 36 + 4 * k);
        over |= (tex[k] & ~LOAD_F32_SIGN) > load_bits_of(SCN_MAX_FACTOR);
    }
    over &= !passed;
    if (over)
        return load_range(L, "prim ", i, "a value is");
    o->kind = SCENE_PRIM_TRIANGLE;
    struct load_scaler sc = load_scaler_at(L);
    uint32_t slow = 0;
    for (int k = 0; k < 3; k++) {
        const uint8_t *c = v + 12 * k;
        o->shape.triangle.v[k] =
            vec3_make(num_from_f32_bits(load_scale_tri_bits(&sc, load_u32(c), &slow)),
                      num_from_f32_bits(load_scale_tri_bits(&sc, load_u32(c + 4), &slow)),
                      num_from_f32_bits(load_scale_tri_bits(&sc, load_u32(c + 8), &slow)));
        o->shape.triangle.tex_u[k] = num_from_f32_bits(tex[k]);
        o->shape.triangle.tex_v[k] = num_from_f32_bits(tex[3 + k]);
    }
    if (slow && L->tri_stated && !passed)
        LOAD_TRY(load_tri_beyond(L, i, v));
    o->shape.triangle.smooth = 0;
    if (!passed && load_sliver(o->shape.triangle.v, L->len_exp))
        return load_bad(L, SCENE_LOAD_ERR_VALUE, "prim ", i,
                        "degenerate or sliver triangle (a height under "
                        "SCN_MIN_TRIANGLE_HEIGHT / 8)");
    return SCENE_LOAD_OK;
}

static const int load_prim_values[] = {
    [SCN_PRIM_TRIANGLE] = SCN_TRIANGLE_VALUES, [SCN_PRIM_ELLIPSOID] = SCN_ELLIPSOID_VALUES,
    [SCN_PRIM_BOX] = SCN_BOX_VALUES,           [SCN_PRIM_DENSITY] = SCN_DENSITY_VALUES,
    [SCN_PRIM_CONE] = SCN_CONE_VALUES,
};

/* A cone's ends and radii (values base, r0, apex, r1): radii not negative
 * nor both 0, ends apart once in num_t. */
static scene_load_status_t load_cone(struct load *L, const uint8_t *v, scene_prim_t *o)
{
    uint32_t r0 = wire_get_u32(v + 12), r1 = wire_get_u32(v + 28);
    int neg = ((r0 & LOAD_F32_SIGN) && !load_zero(r0)) || ((r1 & LOAD_F32_SIGN) && !load_zero(r1));
    if (neg || (load_zero(r0) && load_zero(r1)))
        return SCENE_LOAD_ERR_VALUE;
    o->kind = SCENE_PRIM_CONE;
    o->shape.cone.end[0] = load_lvec3(L, v);
    o->shape.cone.radius[0] = load_len(L, v + 12);
    o->shape.cone.end[1] = load_lvec3(L, v + 16);
    o->shape.cone.radius[1] = load_len(L, v + 28);
    vec3_t a = o->shape.cone.end[0], b = o->shape.cone.end[1];
    if (num_eq(a.x, b.x) && num_eq(a.y, b.y) && num_eq(a.z, b.z))
        return SCENE_LOAD_ERR_VALUE;
    return SCENE_LOAD_OK;
}

/* The primitives, with passed a constant (L->passed: load_geometry). */
LOAD_INLINE scene_load_status_t load_prims_as(struct load *L, scene_prim_t *out,
                                              scene_density_component_t *comps, const int passed)
{
    uint32_t n_mat = L->sec[SCN_SEC_MATERIALS].count;
    uint32_t n_clu = L->sec[SCN_SEC_CLUSTERS].count;
    uint32_t n_comp = L->sec[SCN_SEC_COMPONENTS].present ? L->sec[SCN_SEC_COMPONENTS].count : 0;
    const uint8_t *rec = load_rec(L, SCN_SEC_PRIMS, 0);
    L->scaler = load_scaler_of(L, L->len_exp);
    for (uint32_t i = 0, n = L->sec[SCN_SEC_PRIMS].count; i < n; i++) {
        const uint8_t *p = rec + (size_t)i * SCN_PRIM_SIZE;
        uint16_t kind = wire_get_u16(p + SCN_PRIM_KIND);
        uint16_t mat = wire_get_u16(p + SCN_PRIM_MATERIAL);
        uint32_t clu = load_u32(p + SCN_PRIM_CLUSTER);
        uint32_t first = load_u32(p + SCN_PRIM_FIRST);
        uint32_t count = load_u32(p + SCN_PRIM_COUNT);
        const uint8_t *v = p + SCN_PRIM_VALUES;
        if (kind < SCN_PRIM_TRIANGLE || kind > SCN_PRIM_KINDS)
            return load_bad(L, SCENE_LOAD_ERR_VALUE, "prim ", i, "unknown kind");
        if (mat >= n_mat)
            return load_bad(L, SCENE_LOAD_ERR_INDEX, "prim ", i, "material index out of range");
        if (clu >= n_clu)
            return load_bad(L, SCENE_LOAD_ERR_INDEX, "prim ", i, "cluster index out of range");
        L->len_exp = clu < n_clu ? L->unit_exp + (int)L->cexp[clu] : L->unit_exp;
        if (kind == SCN_PRIM_TRIANGLE && mat < n_mat && clu < n_clu && first == 0 &&
            count == 0) {
            out[i].cluster = clu;
            out[i].material = mat;
            LOAD_TRY(load_triangle(L, i, v, &out[i], passed));
            continue;
        }
        if (kind == SCN_PRIM_TRIANGLE) /* not taken above: a component range */
            return load_bad(L, SCENE_LOAD_ERR_VALUE, "prim ", i,
                            "component range on a primitive that is not a density sphere");
        int nv = load_prim_values[kind];
        int nlen = kind == SCN_PRIM_DENSITY ? 0 : nv;
        if (!load_coords(v, nlen) || !load_factors(v + 4 * nlen, nv - nlen))
            return load_range(L, "prim ", i, "a value is");
        for (int k = nv; k < SCN_PRIM_MAX_VALUES; k++)
            if (load_u32(v + 4 * k) != 0)
                return load_bad(L, SCENE_LOAD_ERR_VALUE, "prim ", i, "unused value not zero");
        if (kind != SCN_PRIM_DENSITY && kind != SCN_PRIM_CONE && (first != 0 || count != 0))
            return load_bad(L, SCENE_LOAD_ERR_VALUE, "prim ", i,
                            "component range on a primitive that is not a density sphere");
        if (kind == SCN_PRIM_CONE && (first > SCN_CONE_CAPPED || count != 0))
            return load_bad(L, SCENE_LOAD_ERR_VALUE, "prim ", i,
                            "a cone's caps are not 0 (open) or 1 (capped), or its count not 0");
        scene_prim_t *o = &out[i];
        o->cluster = clu;
        o->material = mat;
        switch (kind) {
        case SCN_PRIM_ELLIPSOID:
        case SCN_PRIM_BOX:
            for (int k = 3; k < 6; k++)
                if (!load_pos(load_u32(v + 4 * k), SCN_MAX_COORD))
                    return load_bad(L, SCENE_LOAD_ERR_VALUE, "prim ", i,
                                    "a semi-axis or half edge is not > 0");
            if (kind == SCN_PRIM_ELLIPSOID) {
                o->kind = SCENE_PRIM_ELLIPSOID;
                o->shape.ellipsoid.centre = load_lvec3(L, v);
                o->shape.ellipsoid.radius = load_lvec3(L, v + 12);
            } else {
                o->kind = SCENE_PRIM_BOX;
                o->shape.box.centre = load_lvec3(L, v);
                o->shape.box.half = load_lvec3(L, v + 12);
            }
            break;
        case SCN_PRIM_CONE:
            if (load_cone(L, v, o) != SCENE_LOAD_OK)
                return load_bad(L, SCENE_LOAD_ERR_VALUE, "prim ", i,
                                "a cone's radius is negative, both are 0, or its ends meet");
            o->shape.cone.capped = (uint8_t)first;
            break;
        default: /* SCN_PRIM_DENSITY */
            if (!load_pos(load_u32(v), SCN_MAX_FACTOR))
                return load_bad(L, SCENE_LOAD_ERR_VALUE, "prim ", i, "threshold is not > 0");
            if (count < 1 || count > SCN_MAX_DENSITY_COMPONENTS)
                return load_bad(L, SCENE_LOAD_ERR_LIMIT, "prim ", i,
                                "component count not 1..64");
            if (first > n_comp || count > n_comp - first)
                return load_bad(L, SCENE_LOAD_ERR_INDEX, "prim ", i,
                                "components outside the component section");
            o->kind = SCENE_PRIM_DENSITY;
            for (uint32_t k = first; k < first + count; k++) { /* in this cluster */
                const uint8_t *cp = load_rec(L, SCN_SEC_COMPONENTS, k);
                comps[k].centre = load_lvec3(L, cp + SCN_COMPONENT_CENTRE);
                comps[k].radius = load_len(L, cp + SCN_COMPONENT_RADIUS);
            }
            o->shape.density.first = first;
            o->shape.density.count = (uint16_t)count;
            o->shape.density.threshold = load_num(v);
            break;
        }
    }
    return SCENE_LOAD_OK;
}

/* The vertex normals of smooth triangles: each record names a triangle,
 * later than the one before, and holds three unit normals (passed a
 * constant, as load_prims_as's). */
LOAD_INLINE scene_load_status_t load_normals_as(struct load *L, scene_prim_t *prims,
                                                scene_normals_t *out, const int passed)
{
    uint32_t n = L->sec[SCN_SEC_NORMALS].present ? L->sec[SCN_SEC_NORMALS].count : 0;
    uint32_t n_prim = L->sec[SCN_SEC_PRIMS].present ? L->sec[SCN_SEC_PRIMS].count : 0;
    const num_t lo = NUM_C(1.0f - SCN_NORMAL_LENGTH_TOLERANCE);
    const num_t hi = NUM_C(1.0f + SCN_NORMAL_LENGTH_TOLERANCE);
    for (uint32_t i = 0; i < n; i++) {
        const uint8_t *p = load_rec(L, SCN_SEC_NORMALS, i);
        uint32_t prim = load_u32(p + SCN_NORMALS_PRIM);
        if (prim >= n_prim)
            return load_bad(L, SCENE_LOAD_ERR_INDEX, "normals ", i, "prim index out of range");
        if (i > 0 && prim <= load_u32(load_rec(L, SCN_SEC_NORMALS, i - 1) + SCN_NORMALS_PRIM))
            return load_bad(L, SCENE_LOAD_ERR_INDEX, "normals ", i,
                            "prim index not above the previous record's");
        if (prims[prim].kind != SCENE_PRIM_TRIANGLE)
            return load_bad(L, SCENE_LOAD_ERR_VALUE, "normals ", i, "prim is not a triangle");
        if (!passed && !load_factors(p + SCN_NORMALS_N, 9))
            return load_bad(L, SCENE_LOAD_ERR_VALUE, "normals ", i, "a value is not finite");
        for (int k = 0; k < 3; k++) {
            out[i].n[k] = load_vec3(p + SCN_NORMALS_N + 12 * k);
            if (passed)
                continue;
            num_t len = vec3_length(out[i].n[k]);
            if (num_lt(len, lo) || num_gt(len, hi))
                return load_bad(L, SCENE_LOAD_ERR_VALUE, "normals ", i,
                                "a normal is not of unit length");
        }
        prims[prim].shape.triangle.smooth = i + 1;
    }
    return SCENE_LOAD_OK;
}

/* The primitives and the vertex normals, with passed a constant. */
LOAD_INLINE scene_load_status_t load_geometry_as(struct load *L, scene_prim_t *prims,
                                                 scene_density_component_t *comps,
                                                 scene_normals_t *normals, const int passed)
{
    scene_load_status_t st = load_prims_as(L, prims, comps, passed);
    return st == SCENE_LOAD_OK ? load_normals_as(L, prims, normals, passed) : st;
}

/* load_geometry_as for a load that checks the values and for one that does
 * not (L->passed), each compiled apart, not inlined into one function: a
 * load that checks pays nothing for the one that does not. */
static __attribute__((noinline)) scene_load_status_t
load_geometry_checked(struct load *L, scene_prim_t *prims, scene_density_component_t *comps,
                      scene_normals_t *normals)
{
    return load_geometry_as(L, prims, comps, normals, 0);
}

static __attribute__((noinline)) scene_load_status_t
load_geometry_passed(struct load *L, scene_prim_t *prims, scene_density_component_t *comps,
                     scene_normals_t *normals)
{
    return load_geometry_as(L, prims, comps, normals, 1);
}

/* ------------------------------------------------- scaled to the scene */

/* The mantissa bits of 2/sqrt(3), rounded up: load_matrix_exp */
#define LOAD_MANT_2_OVER_SQRT3 0x13cd3bu

/* The bits of the largest |value| of the n reals at p: the magnitude bits
 * of finite values order as the values do, and every value not finite or
 * beyond a limit has bits above the limit's. */
LOAD_INLINE uint32_t load_max_bits(const uint8_t *p, int n)
{
    uint32_t big = 0;
#pragma GCC unroll 9
    for (int i = 0; i < n; i++) {
        uint32_t m = load_u32(p + 4 * i) & ~LOAD_F32_SIGN;
        big = m > big ? m : big;
    }
    return big;
}

/* load_max_exp of the n reals at p whose load_max_bits are big. */
LOAD_INLINE int32_t load_max_exp_of(const uint8_t *p, int n, uint32_t big, int32_t shift,
                                    int32_t most)
{
    /* the largest magnitude's exponent field, when it is finite: the
     * magnitude bits of finite values order as the values do */
    int32_t field = (int32_t)(big >> 23);
    if (field != 255)
        return field != 0 && field - 127 + shift > most ? field - 127 + shift : most;
    for (int i = 0; i < n; i++) {
        int32_t field = (int32_t)((load_u32(p + 4 * i) & LOAD_F32_EXP_MASK) >> 23);
        if (field != 0 && field != 255 && field - 127 + shift > most)
            most = field - 127 + shift;
    }
    return most;
}

/* The largest of most and shift + e over the n reals at p, |value| in
 * [2^e, 2^(e+1)); zeros, subnormals and not-finite values (left to the
 * checks that follow) count as none. */
LOAD_INLINE int32_t load_max_exp(const uint8_t *p, int n, int32_t shift, int32_t most)
{
    return load_max_exp_of(p, n, load_max_bits(p, n), shift, most);
}

/* A cluster's static 3x3 part, as a power of two: floor(log2(sqrt(3)
 * |largest entry|)), so a rotation gives 0 (its largest entry is 1/sqrt(3)
 * .. 1) and a rotation times 2^k gives k; 0 for a zero matrix. */
static int32_t load_matrix_exp(const uint8_t *m)
{
    uint32_t big = 0;
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 3; k++) {
            uint32_t bits = load_u32(m + 4 * (4 * r + k)) & ~LOAD_F32_SIGN;
            if (load_finite(bits) && bits > big)
                big = bits;
        }
    if ((big >> 23) == 0)
        return 0;
    return (int32_t)(big >> 23) - 127 + ((big & 0x7fffffu) >= LOAD_MANT_2_OVER_SQRT3);
}

/* load_scale's pass over the clusters: each one's cexp and kexp (L's), and
 * the largest geometry exponent of their keys' and matrices' lengths. */
static int32_t load_scale_clusters(struct load *L)
{
    uint32_t n_clu = L->sec[SCN_SEC_CLUSTERS].count, n_keys = L->sec[SCN_SEC_KEYS].count;
    int32_t geom = LOAD_EXP_NONE; /* the geometry's largest, in world units */
    int32_t *cexp = L->cexp, *kexp = L->kexp; /* read once, not after each store */
    const uint8_t *clusters = load_rec(L, SCN_SEC_CLUSTERS, 0);
    for (uint32_t i = 0; i < n_clu; i++) {
        const uint8_t *p = clusters + (size_t)i * SCN_CLUSTER_SIZE;
        uint32_t parent = load_u32(p + SCN_CLUSTER_PARENT);
        uint32_t kf = load_u32(p + SCN_CLUSTER_KEY_FIRST);
        uint32_t kc = load_u32(p + SCN_CLUSTER_KEY_COUNT);
        int32_t cp = i > 0 && parent < i ? cexp[parent] : 0;
        if (load_cluster_plain(p)) { /* no length, the identity */
            kexp[i] = LOAD_KEXP_PLAIN;
            cexp[i] = cp;
            continue;
        }
        int32_t ks = LOAD_EXP_NONE;
        if (kf <= n_keys && kc <= n_keys - kf)
            for (uint32_t k = kf; k < kf + kc; k++) {
                const uint8_t *kp = load_rec(L, SCN_SEC_KEYS, k);
                geom = load_max_exp(kp + SCN_KEY_TRANSLATE, 3, cp, geom);
                ks = load_max_exp(kp + SCN_KEY_SCALE, 3, 0, ks);
            }
        kexp[i] = ks == LOAD_EXP_NONE ? 0 : ks;
        for (int r = 0; r < 3; r++)
            geom = load_max_exp(p + SCN_CLUSTER_MATRIX + 4 * (4 * r + 3), 1, cp + kexp[i],
                                geom);
        cexp[i] = cp + kexp[i] + load_matrix_exp(p + SCN_CLUSTER_MATRIX);
    }
    return geom;
}

/* The largest of geom and triangle p's coordinates' exponents (its
 * cluster's c added); L->triangle_coords_over. */
LOAD_INLINE int32_t load_scale_triangle(struct load *L, const uint8_t *p, int32_t c, int32_t geom)
{
    uint32_t big = load_max_bits(p + SCN_PRIM_VALUES, 9);
    L->triangle_coords_over |= big > load_bits_of(SCN_MAX_COORD);
    return load_max_exp_of(p + SCN_PRIM_VALUES, 9, big, c, geom);
}

/* load_scale's pass over the primitives: the largest of geom and their
 * lengths' exponents (the triangles' as the scene states them, if it does:
 * load_extent); L->triangle_coords_over. */
static int32_t load_scale_prims(struct load *L, int32_t geom)
{
    if (L->tri_stated && L->tri_exp > geom)
        geom = L->tri_exp;
    uint32_t n_clu = L->sec[SCN_SEC_CLUSTERS].count;
    uint32_t n_comp = L->sec[SCN_SEC_COMPONENTS].count;
    const int32_t *cexp = L->cexp; /* read once, not after each store */
    const uint8_t *prims = load_rec(L, SCN_SEC_PRIMS, 0);
    for (uint32_t i = 0, n = L->sec[SCN_SEC_PRIMS].count; i < n; i++) {
        const uint8_t *p = prims + (size_t)i * SCN_PRIM_SIZE;
        uint16_t kind = wire_get_u16(p + SCN_PRIM_KIND);
        uint32_t clu = load_u32(p + SCN_PRIM_CLUSTER);
        int32_t c = clu < n_clu ? cexp[clu] : 0;
        if (kind == SCN_PRIM_TRIANGLE) { /* the common case */
            if (!L->tri_stated)
                geom = load_scale_triangle(L, p, c, geom);
            continue;
        }
        int n = kind == SCN_PRIM_DENSITY ? 0 : kind == SCN_PRIM_CONE ? SCN_CONE_VALUES : 6;
        geom = load_max_exp(p + SCN_PRIM_VALUES, n, c, geom);
        uint32_t first = load_u32(p + SCN_PRIM_FIRST), count = load_u32(p + SCN_PRIM_COUNT);
        if (kind == SCN_PRIM_DENSITY && first <= n_comp && count <= n_comp - first)
            for (uint32_t k = first; k < first + count; k++)
                geom = load_max_exp(load_rec(L, SCN_SEC_COMPONENTS, k) + SCN_COMPONENT_CENTRE, 4,
                                    c, geom);
    }
    return geom;
}

/* The triangles' exponent the scene states (its EXTENT section), if it
 * does: L->tri_stated and tri_exp. */
static scene_load_status_t load_extent(struct load *L)
{
    if (!L->sec[SCN_SEC_EXTENT].present || L->sec[SCN_SEC_EXTENT].count == 0)
        return SCENE_LOAD_OK;
    uint32_t bits = load_u32(load_rec(L, SCN_SEC_EXTENT, 0) + SCN_EXTENT_TRI_EXP);
    int64_t e = bits <= INT32_MAX ? (int64_t)bits : (int64_t)bits - 4294967296LL;
    if (bits != SCN_EXTENT_NO_TRIANGLE && (e < -SCN_EXTENT_EXP_LIMIT || e > SCN_EXTENT_EXP_LIMIT))
        return load_fail(L, SCENE_LOAD_ERR_VALUE, "the EXTENT section's exponent %ld is beyond "
                         "+-%ld", (long)e, (long)SCN_EXTENT_EXP_LIMIT);
    L->tri_stated = 1;
    L->tri_exp = bits == SCN_EXTENT_NO_TRIANGLE ? LOAD_EXP_NONE : (int32_t)e;
    return SCENE_LOAD_OK;
}

/* The largest of geom and the exponents of the eye, the look-at point and
 * the point and spot lights, keyed or not. */
static int32_t load_scale_view(struct load *L, int32_t geom)
{
    int32_t most = load_max_exp(load_rec(L, SCN_SEC_VIEW, 0) + SCN_VIEW_EYE, 6, 0, geom);
    for (uint32_t i = 0; i < L->sec[SCN_SEC_LIGHTS].count; i++) {
        const uint8_t *p = load_rec(L, SCN_SEC_LIGHTS, i);
        if (load_u32(p + SCN_LIGHT_KIND) != SCN_LIGHT_PARALLEL)
            most = load_max_exp(p + SCN_LIGHT_POSITION, 3, 0, most);
    }
    uint32_t n_light = L->sec[SCN_SEC_LIGHTS].count;
    for (uint32_t i = 0; i < L->sec[SCN_SEC_VIEW_KEYS].count; i++) {
        const uint8_t *p = load_rec(L, SCN_SEC_VIEW_KEYS, i);
        uint32_t target = load_u32(p + SCN_VKEY_TARGET);
        if (target == SCN_VKEY_CAMERA)
            most = load_max_exp(p + SCN_VKEY_EYE, 6, 0, most);
        else if (target < n_light && load_u32(load_rec(L, SCN_SEC_LIGHTS, target) +
                                                  SCN_LIGHT_KIND) != SCN_LIGHT_PARALLEL)
            most = load_max_exp(p + SCN_VKEY_POSITION, 3, 0, most);
    }
    return most;
}

/* unit_exp and tol_exp (scene.h), and each cluster's exponent, before any
 * value enters num_t.  A cluster's coordinates are stored times
 * 2^(unit_exp + cexp): cexp is its parent's plus the power of two of its
 * keys' largest scale (kexp) and of its static matrix, whose entries and
 * key scales lose those powers of two, so they stay near 1 and the stored
 * coordinates follow the world's: a cluster scaled by 2^k holds the values
 * of its contents scaled by 2^k in its parent, bit for bit.  unit_exp
 * brings the largest |length| in world units (cluster contents times their
 * clusters' powers of two, eye, look-at, point and spot lights) to 8..16;
 * tol_exp follows the geometry's (all but the eye and the lights).  The
 * values are read unchecked (the checks come after): an index out of
 * range counts as the root.  Known already (scene_load_known_t.passed):
 * the clusters' exponents alone. */
_Static_assert((long long)SCN_MAX_COORD < (1LL << 62) && RENDER_NORM_EXP + 1 - RENDER_NORM_EXP_MIN > 62,
               "SCN_MAX_COORD beyond what RENDER_NORM_EXP_MIN scales to 8..16");
_Static_assert((long)SCN_MAX_FACTOR <= NUM_COORD_LIMIT, "SCN_MAX_FACTOR beyond the fixed range");
static scene_load_status_t load_scale(struct load *L, scene_t *s)
{
    int32_t geom = load_scale_clusters(L);
    if (L->passed) {
        L->unit_exp = L->len_exp = (int)L->known->unit_exp;
        s->unit_exp = L->known->unit_exp;
        s->tol_exp = L->known->tol_exp;
        return SCENE_LOAD_OK; /* triangle_coords_over 0: every one was in range */
    }
    LOAD_TRY(load_extent(L));
    geom = load_scale_prims(L, geom);
    int32_t most = load_scale_view(L, geom);
    int32_t e = most == LOAD_EXP_NONE ? 0 : RENDER_NORM_EXP - most; /* the largest |length|
                                                     is in [2^most, 2^(most+1)) */
    if (e < RENDER_NORM_EXP_MIN || e > RENDER_NORM_EXP_MAX)
            return load_fail(L, SCENE_LOAD_ERR_VALUE, "the scene's largest length, its clusters' "
                         "scales included, is 2^%ld: beyond 2^%ld..2^%ld", (long)most,
                         (long)(RENDER_NORM_EXP - RENDER_NORM_EXP_MAX),
                         (long)(RENDER_NORM_EXP - RENDER_NORM_EXP_MIN));
    int32_t t = 0;
    if (geom != LOAD_EXP_NONE) /* the geometry's largest length, scaled by 2^e, to 8..16 */
        t = geom - most + RENDER_TOL_SLACK_EXP;
    t = t > 0 ? 0 : t;
    L->unit_exp = (int)e;
    L->len_exp = (int)e;
    s->unit_exp = e;
    s->tol_exp = t < RENDER_TOL_EXP_MIN ? RENDER_TOL_EXP_MIN : t;
    return SCENE_LOAD_OK;
}

/* ---------------------------------------------------------------- entry */

#define LOAD_ALLOC(arena, type, n) ARENA_NEW_ARRAY((arena), type, (n) ? (n) : 1)

scene_load_status_t scene_load(const uint8_t *buf, size_t len, arena_t *arena, scene_t *out,
                               scene_load_error_t *err)
{
    return scene_load_summed(buf, len, NULL, arena, out, err);
}

scene_load_status_t scene_load_triangle_exp(const uint8_t *buf, size_t len, arena_t *arena,
                                            uint32_t *bits, scene_load_error_t *err)
{
    struct load L;
    memset(&L, 0, sizeof L);
    L.buf = buf;
    L.err = err;
    L.crc_later = 1;
    err->status = SCENE_LOAD_OK;
    err->message[0] = 0;
    LOAD_TRY(load_header(&L, buf ? len : 0));
    size_t mark = arena->used;
    uint32_t n_clu = L.sec[SCN_SEC_CLUSTERS].count;
    L.cexp = LOAD_ALLOC(arena, int32_t, n_clu);
    L.kexp = LOAD_ALLOC(arena, int32_t, n_clu);
    if (!L.cexp || !L.kexp) {
        arena_release_to(arena, mark);
        return load_fail(&L, SCENE_LOAD_ERR_ARENA, "arena too small for the clusters' exponents");
    }
    load_scale_clusters(&L);
    int32_t geom = LOAD_EXP_NONE;
    const uint8_t *prims = load_rec(&L, SCN_SEC_PRIMS, 0);
    for (uint32_t i = 0, n = L.sec[SCN_SEC_PRIMS].count; i < n; i++) {
        const uint8_t *p = prims + (size_t)i * SCN_PRIM_SIZE;
        uint32_t clu = load_u32(p + SCN_PRIM_CLUSTER);
        if (wire_get_u16(p + SCN_PRIM_KIND) == SCN_PRIM_TRIANGLE)
            geom = load_scale_triangle(&L, p, clu < n_clu ? L.cexp[clu] : 0, geom);
    }
    arena_release_to(arena, mark);
    *bits = geom == LOAD_EXP_NONE ? SCN_EXTENT_NO_TRIANGLE : (uint32_t)geom;
    return SCENE_LOAD_OK;
}

/* The scene's index: the load that passed's, where it hands one over
 * (scene_load_known_t.index) of a scene of these counts, else worked out. */
static render_status_t load_index(const struct load *L, arena_t *arena, scene_t *out)
{
    const scene_index_ints_t *same = L->passed ? &L->known->index : NULL;
    if (same && same->groups && same->cluster_count == out->cluster_count &&
        same->prim_count == out->prim_count && same->normals_count == out->normals_count)
        return render_scene_index_same(out, arena, same, &out->index);
    return render_scene_index(out, arena, &out->index);
}

scene_load_known_t scene_load_known_of(const scene_t *s, uint32_t body_sum)
{
    scene_load_known_t k = {body_sum, 1, s->unit_exp, s->tol_exp, {0}};
#if !defined(LINKS1_NUM_FIXED)
    /* An IEEE load's values widen exactly: another arithmetic's index
     * makes the same decisions (a fixed point format rounds them: a
     * cluster plain there, or two normals equal, may not be so in double) */
    k.index = render_scene_index_ints(s);
#endif
    return k;
}

scene_load_status_t scene_load_summed(const uint8_t *buf, size_t len,
                                      const scene_load_known_t *known, arena_t *arena,
                                      scene_t *out, scene_load_error_t *err)
{
    struct load L;
    memset(&L, 0, sizeof L);
    L.buf = buf;
    L.err = err;
    L.known = known;
    L.passed = known && known->passed;
    err->status = SCENE_LOAD_OK;
    err->message[0] = 0;
    memset(out, 0, sizeof *out);
    LOAD_TRY(load_header(&L, buf ? len : 0));

    uint32_t n_light = L.sec[SCN_SEC_LIGHTS].count, n_mat = L.sec[SCN_SEC_MATERIALS].count;
    uint32_t n_map = L.sec[SCN_SEC_MAPS].count, n_tex = L.sec[SCN_SEC_TEXELS].count;
    uint32_t n_clu = L.sec[SCN_SEC_CLUSTERS].count, n_prim = L.sec[SCN_SEC_PRIMS].count;
    uint32_t n_comp = L.sec[SCN_SEC_COMPONENTS].count, n_key = L.sec[SCN_SEC_KEYS].count;
    uint32_t n_nrm = L.sec[SCN_SEC_NORMALS].count, n_vkey = L.sec[SCN_SEC_VIEW_KEYS].count;
    size_t mark = arena->used;
    scene_light_t *lights = LOAD_ALLOC(arena, scene_light_t, n_light);
    scene_material_t *mats = LOAD_ALLOC(arena, scene_material_t, n_mat);
    scene_map_t *maps = LOAD_ALLOC(arena, scene_map_t, n_map);
    uint8_t *texels = LOAD_ALLOC(arena, uint8_t, n_tex);
    scene_cluster_t *clusters = LOAD_ALLOC(arena, scene_cluster_t, n_clu);
    scene_prim_t *prims = LOAD_ALLOC(arena, scene_prim_t, n_prim);
    scene_density_component_t *comps = LOAD_ALLOC(arena, scene_density_component_t, n_comp);
    scene_key_t *keys = LOAD_ALLOC(arena, scene_key_t, n_key);
    scene_normals_t *normals = LOAD_ALLOC(arena, scene_normals_t, n_nrm);
    scene_view_key_t *view_keys = LOAD_ALLOC(arena, scene_view_key_t, n_vkey);
    size_t scratch = arena->used;
    uint8_t *nesting = LOAD_ALLOC(arena, uint8_t, n_clu); /* scratch, released below */
    L.cexp = LOAD_ALLOC(arena, int32_t, n_clu);
    L.kexp = LOAD_ALLOC(arena, int32_t, n_clu);
    if (!lights || !mats || !maps || !texels || !clusters || !prims || !comps || !keys ||
        !normals || !view_keys || !nesting || !L.cexp || !L.kexp) {
        size_t need = arena->failed_request;
        arena_release_to(arena, mark);
        return load_fail(&L, SCENE_LOAD_ERR_ARENA, "arena too small for the scene: %ld bytes free, "
                         "a request of %ld bytes failed", (long)(arena->size - mark), (long)need);
    }
    scene_load_status_t st = load_scale(&L, out);
    if (st == SCENE_LOAD_OK)
        st = load_view(&L, out);
    if (st == SCENE_LOAD_OK)
        st = load_lights(&L, lights);
    if (st == SCENE_LOAD_OK)
        st = load_view_keys(&L, view_keys);
    if (st == SCENE_LOAD_OK)
        st = load_haze(&L, out);
    if (st == SCENE_LOAD_OK)
        st = load_maps(&L, maps, texels);
    if (st == SCENE_LOAD_OK)
        st = load_materials(&L, maps, mats);
    if (st == SCENE_LOAD_OK)
        st = load_keys(&L, keys);
    if (st == SCENE_LOAD_OK)
        st = load_clusters(&L, keys, clusters, nesting);
    if (st == SCENE_LOAD_OK)
        st = load_components(&L, comps);
    if (st == SCENE_LOAD_OK)
        st = L.passed ? load_geometry_passed(&L, prims, comps, normals)
                      : load_geometry_checked(&L, prims, comps, normals);
    if (st == SCENE_LOAD_OK && n_light == 0)
        st = load_fail(&L, SCENE_LOAD_ERR_MISSING, "the scene has no light");
    if (st != SCENE_LOAD_OK) {
        arena_release_to(arena, mark);
        memset(out, 0, sizeof *out);
        return st;
    }
    arena_release_to(arena, scratch);
    out->lights = lights;
    out->light_count = (uint16_t)n_light;
    out->materials = mats;
    out->material_count = (uint16_t)n_mat;
    out->maps = maps;
    out->map_count = (uint16_t)n_map;
    out->clusters = clusters;
    out->cluster_count = n_clu;
    out->keys = keys;
    out->key_count = n_key;
    out->prims = prims;
    out->prim_count = n_prim;
    out->density_components = comps;
    out->density_component_count = n_comp;
    out->normals = normals;
    out->normals_count = n_nrm;
    out->view_keys = view_keys;
    out->view_key_count = n_vkey;
    /* the static structure every frame's preparation reads, once a load */
    render_status_t rs = load_index(&L, arena, out);
    if (rs != RENDER_OK) {
        arena_release_to(arena, mark);
        memset(out, 0, sizeof *out);
        return load_fail(&L, rs == RENDER_ERR_ARENA ? SCENE_LOAD_ERR_ARENA : SCENE_LOAD_ERR_TREE,
                         "the scene's index: %s", render_status_name(rs));
    }
    return SCENE_LOAD_OK;
}

/* The maps render_scene_index keeps at most (scene_index_t.parent_maps):
 * two for the root and for each other cluster whose record is not plain
 * (load_cluster_plain), which alone may have maps of their own. */
static uint32_t load_shape_maps(const struct load *L)
{
    uint32_t own = 1;
    for (uint32_t i = 1; i < L->sec[SCN_SEC_CLUSTERS].count; i++)
        own += !load_cluster_plain(load_rec(L, SCN_SEC_CLUSTERS, i));
    return 2 * own;
}

static scene_load_status_t load_shape(const uint8_t *buf, size_t len, scene_t *shape,
                                      uint32_t *texel_bytes, scene_load_error_t *err,
                                      int crc_later, int count_maps)
{
    struct load L;
    memset(&L, 0, sizeof L);
    L.buf = buf;
    L.err = err;
    L.crc_later = crc_later;
    err->status = SCENE_LOAD_OK;
    err->message[0] = 0;
    memset(shape, 0, sizeof *shape);
    *texel_bytes = 0;
    LOAD_TRY(load_header(&L, buf ? len : 0));
    shape->light_count = (uint16_t)L.sec[SCN_SEC_LIGHTS].count;
    shape->material_count = (uint16_t)L.sec[SCN_SEC_MATERIALS].count;
    shape->map_count = (uint16_t)L.sec[SCN_SEC_MAPS].count;
    shape->cluster_count = L.sec[SCN_SEC_CLUSTERS].count;
    shape->key_count = L.sec[SCN_SEC_KEYS].count;
    shape->prim_count = L.sec[SCN_SEC_PRIMS].count;
    shape->density_component_count = L.sec[SCN_SEC_COMPONENTS].count;
    shape->normals_count = L.sec[SCN_SEC_NORMALS].count;
    shape->view_key_count = L.sec[SCN_SEC_VIEW_KEYS].count;
    *texel_bytes = L.sec[SCN_SEC_TEXELS].count;
    if (count_maps)
        shape->index.parent_map_count = load_shape_maps(&L);
    return SCENE_LOAD_OK;
}

scene_load_status_t scene_load_shape(const uint8_t *buf, size_t len, scene_t *shape,
                                     uint32_t *texel_bytes, scene_load_error_t *err)
{
    return load_shape(buf, len, shape, texel_bytes, err, 0, 0);
}

scene_load_status_t scene_load_shape_before_load(const uint8_t *buf, size_t len, scene_t *shape,
                                                 uint32_t *texel_bytes, scene_load_error_t *err)
{
    return load_shape(buf, len, shape, texel_bytes, err, 1, 0);
}

scene_load_status_t scene_load_shape_maps(const uint8_t *buf, size_t len, int crc_later,
                                          scene_t *shape, uint32_t *texel_bytes,
                                          scene_load_error_t *err)
{
    return load_shape(buf, len, shape, texel_bytes, err, crc_later, 1);
}

/* Keep in step with the allocations of scene_load above: each array (at
 * least one element), the nesting and the exponent scratch, each padded by at most
 * ARENA_MAX_ALIGN. */
size_t scene_load_bytes_layout(const scene_t *shape, uint32_t texel_bytes,
                               const render_layout_t *lay)
{
#define LOAD_BYTES(size, n) ((size) * (size_t)((n) ? (n) : 1))
    return LOAD_BYTES(lay->light, shape->light_count) +
           LOAD_BYTES(lay->material, shape->material_count) +
           LOAD_BYTES(lay->map, shape->map_count) + LOAD_BYTES(1, texel_bytes) +
           LOAD_BYTES(lay->cluster, shape->cluster_count) +
           LOAD_BYTES(lay->prim, shape->prim_count) +
           LOAD_BYTES(lay->component, shape->density_component_count) +
           LOAD_BYTES(lay->key, shape->key_count) +
           LOAD_BYTES(lay->normals, shape->normals_count) +
           LOAD_BYTES(lay->view_key, shape->view_key_count) +
           LOAD_BYTES(1, shape->cluster_count) + LOAD_BYTES(8, shape->cluster_count) +
           13 * ARENA_MAX_ALIGN + render_scene_index_bytes_layout(shape, lay);
#undef LOAD_BYTES
}

size_t scene_load_bytes(const scene_t *shape, uint32_t texel_bytes)
{
    return scene_load_bytes_layout(shape, texel_bytes, &render_layout_native);
}

const char *scene_load_status_name(scene_load_status_t status)
{
    switch (status) {
    case SCENE_LOAD_OK: return "ok";
    case SCENE_LOAD_ERR_TRUNCATED: return "truncated";
    case SCENE_LOAD_ERR_MAGIC: return "bad magic";
    case SCENE_LOAD_ERR_VERSION: return "unsupported version";
    case SCENE_LOAD_ERR_SIZE: return "bad size";
    case SCENE_LOAD_ERR_CRC: return "checksum mismatch";
    case SCENE_LOAD_ERR_SECTION: return "bad section table";
    case SCENE_LOAD_ERR_MISSING: return "missing section";
    case SCENE_LOAD_ERR_LIMIT: return "over a limit";
    case SCENE_LOAD_ERR_INDEX: return "index out of range";
    case SCENE_LOAD_ERR_VALUE: return "bad value";
    case SCENE_LOAD_ERR_TREE: return "bad cluster tree";
    case SCENE_LOAD_ERR_ARENA: return "arena too small";
    }
    return "unknown status";
}
