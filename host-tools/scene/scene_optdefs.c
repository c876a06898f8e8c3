/* scene_optdefs.c: the definitions of the scene options (scene_opts.h),
 * apart from their reader (scene_opts.c): scene_file.c names them and
 * writes them as words from here, in every program that reads a scene
 * file, those without the option reader too. */
#include "host-tools/scene/scene_opts.h"

#include <stddef.h>

const struct cli_optdef scene_optdefs[] = {
    {"size", "WxH", SCENE_OPT_SIZE, "render at this size instead of the scene's"},
    {"max-depth", "D", SCENE_OPT_MAX_DEPTH, "the scene's recursion depth instead (0..16)"},
    {"min-weight", "W", SCENE_OPT_MIN_WEIGHT,
     "adaptive depth: rays whose weight (the product of src and trc)\n"
     "falls below W are not traced (0..1; scenes default 1/512)"},
    {"density-steps", "N", SCENE_OPT_DENSITY_STEPS,
     "steps of a density sphere's root finder (2..256; scenes\n"
     "default 24): a feature thinner than a step is missed"},
    {"refractionless", "on|off", SCENE_OPT_REFRACTIONLESS,
     "transmission past the depth limit without bending"},
    {"refraction", "on|off", SCENE_OPT_REFRACTION, "off: transmitted rays never bend, at any depth"},
    {"no-auto-hierarchy", NULL, SCENE_OPT_NO_AUTO_HIERARCHY,
     "compile without the automatic hierarchy"},
    {"mark-lost", NULL, SCENE_OPT_MARK_LOST, "paint pixels that lost precision magenta"},
    {"check-lost", NULL, SCENE_OPT_CHECK_LOST,
     "trace a pixel that lost precision again in double only to check\n"
     "it: it counts as lost (and --mark-lost paints it) when double is\n"
     "more than 2/255 away; the image keeps this arithmetic's colours"},
    {"world-space", NULL, SCENE_OPT_WORLD_SPACE,
     "the DM leaves the scene in world coordinates and the NCs turn the\n"
     "camera rays: a frame whose cluster keys did not move keeps the\n"
     "frame before's primitives (no screen clipping)"},
    {"paper", NULL, SCENE_OPT_PAPER,
     "paper mode (as options { paper on }): every choice the paper made;\n"
     "an option given beside it wins; one line says what was set"},
    {"textures-from", "DIR", SCENE_OPT_TEXTURES_FROM,
     "a map's image may also come from below DIR (up to 4; not /, a\n"
     "directory just under / or your home)"},
    {"spd-rules", NULL, SCENE_OPT_SPD_RULES,
     "Haines's rules for timing the SPD: 512x512, rays at the pixel\n"
     "corners (each pixel the mean of its four), depth 5 counting the\n"
     "camera ray, no adaptive depth, refraction by Snell, shadow rays;\n"
     "prints 'spd: eye_hit N reflect N refract N shadow N preprocess S\n"
     "trace S' (an option given beside it wins)"},
    {"aa", "N", SCENE_OPT_AA,
     "anti-aliasing (Whitted's adaptive scheme; as options { aa N }):\n"
     "rays at the pixel corners, shared, and a pixel cut into four\n"
     "where its corners differ by more than --aa-threshold, at most N\n"
     "times (0..4; 0 = the mean of the corner rays); off by default\n"
     "and in paper mode (given beside --paper, it wins)"},
    {"aa-threshold", "T", SCENE_OPT_AA_THRESHOLD,
     "anti-aliasing's threshold (0..1; scenes default 0.1): the largest\n"
     "difference of a channel between a quad's four corner colours\n"
     "(before clamping, 1 = full scale) left uncut"},
    {"no-aa", NULL, SCENE_OPT_NO_AA, "no anti-aliasing, whatever the scene says"},
    CLI_OPTDEF_END,
};

const char *scene_opts_name(int code)
{
    for (const struct cli_optdef *d = scene_optdefs; d->name; d++)
        if (d->code == code)
            return d->name;
    return NULL;
}
