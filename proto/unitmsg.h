/* unitmsg.h: what the unit computers say to each other over the serial
 * lines (struct line_msg.type, drivers/serial/linemsg.h) and the payload of
 * each (little-endian, proto/wire.h).  In proto/ because the host's replay
 * of a frame (host-tools/trace/replay.h) puts the same bytes on its lines. */
#ifndef LINKS1_PROTO_UNITMSG_H
#define LINKS1_PROTO_UNITMSG_H

/* Every line message starts with a header of this many bytes: u16 type,
 * u16 len, u32 seq, u32 crc32 of the payload (drivers/serial/linemsg.h). */
#define LINEMSG_HEADER_SIZE 12

enum unit_msg {
    MSG_PING = 1,            /* u32 token: answer MSG_PONG with the same token */
    MSG_PONG = 2,            /* u32 token */
    MSG_PING_NCS = 3,        /* DM->RC: ping every NC -> MSG_PING_NCS_DONE */
    MSG_PING_NCS_DONE = 4,   /* u32 NCs answering, u32 NCs, u32 first silent core or ~0 */
    MSG_IMSU_PAIR = 5,       /* DM->RC: you hold my block now: u32 bytes, u32 crc,
                              * u32 seed for your answer */
    MSG_IMSU_MIDWRITE = 6,   /* RC->DM: I am inside a write: try to swap now */
    MSG_IMSU_MIDWRITE_SEEN = 7, /* DM->RC: i32 what my swap attempt returned */
    MSG_IMSU_PAIR_DONE = 8,  /* RC->DM: i32 status, u32 crc of what I wrote, text */
    MSG_IMSU_BCAST = 9,      /* DM->RC: broadcast test: u32 bytes, u32 seed */
    MSG_IMSU_BCAST_DONE = 10,/* RC->DM: u32 NCs with the right data, u32 NCs,
                              * u32 misuse checks failed */
    MSG_BCAST_READ = 11,     /* RC->NC: read the broadcast block: u32 bytes */
    MSG_BCAST_READ_DONE = 12,/* NC->RC: i32 read status, u32 crc, u32 generation,
                              * i32 status of a forbidden write attempt */
    MSG_STRESS = 13,         /* DM->RC, RC->NC: u32 messages per stream */
    MSG_STRESS_DATA = 14,    /* a stress message: generated payload */
    MSG_STRESS_REPORT = 15,  /* u64 bytes received and checked, u32 errors,
                              * u32 lines skipped (halted NCs) */
    MSG_FAULT = 16,          /* u16 core, u8 kind: that core faults on purpose */
    MSG_FAULT_ACK = 17,      /* i32 status: 0 = the target is about to fault */
    /* Rendering (roles/gigs.h; roles/dm_render.c, rc_render.c, nc_render.c): */
    MSG_RENDER_FRAME = 18,   /* DM->RC: the prepared frame is in the IMSU block
                              * just swapped to you: struct link_render_args
                              * (proto/render_link.h), then the fault plan */
    MSG_RENDER_PROGRESS = 19,/* RC->DM: u32 areas done, u32 areas total, u32 pixels
                              * in the frame memory, u32 pixels of the frame */
    MSG_RENDER_DONE = 20,    /* RC->DM: i32 status; 0: gigs_frame_result
                              * (GIGS_RESULT_SIZE); else text naming the problem */
    MSG_NC_START = 21,       /* RC->NC: the frame is in the broadcast block:
                              * u8 flags, u8 clipping (enum link_clip), u16 0,
                              * u32 pixels of the largest area
                              * (MSG_NC_START_SIZE); then, while areas are
                              * left, the NC's first area as an MSG_NC_AREA's
                              * payload (word-aligned) */
    MSG_NC_AREA = 22,        /* RC->NC: u16 x, y, w, h: render this area
                              * (MSG_NC_AREA_SIZE); a planned failure adds u8
                              * kind, u8 0, u16 row (MSG_NC_AREA_INJECT_SIZE) */
    MSG_NC_STOP = 23,        /* RC->NC: no more areas: let go of the block */
    MSG_NC_REQ = 24,         /* NC->RC: i32 status: >= 0, next area please, and
                              * the areas this NC finished in the frame (their
                              * pixels are in the DC); < 0: this NC cannot
                              * render, text follows */
    MSG_NC_STOPPED = 25,     /* NC->RC: u32 private high-water mark, then the
                              * frame's render stats (GIGS_STATS_SIZE) */
    MSG_NC_DONE = 26,        /* NC->RC: i32 areas finished in the frame: an NC
                              * that asked ahead finished its area before the
                              * answer came (no new request) */
    MSG_LATENCY = 27,        /* DM->RC: u32 rounds, u16 core: time that many ping
                              * round trips to NC core -> MSG_LATENCY_DONE */
    MSG_LATENCY_DONE = 28,   /* RC->DM: i32 status (0, or the line error of the
                              * round that failed), u32 rounds done, then u32 min,
                              * median, max round trip in ktime ticks */
};

/* MSG_NC_AREA's payload: four u16 (areas.h: sides <= AREAS_MAX_DIM), half
 * of four u32: the RC checksums and copies it once per area request. */
#define MSG_NC_AREA_SIZE 8
#define MSG_NC_START_SIZE 8
/* MSG_NC_REQ's and MSG_NC_DONE's payload: the i32 status (a refusal's
 * text follows it). */
#define MSG_NC_REQ_SIZE 4
#define MSG_NC_AREA_INJECT_SIZE 12

#endif
