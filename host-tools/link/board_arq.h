/* board_arq.h: the state of the host's go-back-N retransmission
 * (proto/link_arq.h) in one link session.  Private to host-tools/link/
 * (and the session's white-box tests): the rest of the tool sees only
 * board_arq_failed() and board_report_link_errors(). */
#ifndef LINKS1_HOST_LINK_BOARD_ARQ_H
#define LINKS1_HOST_LINK_BOARD_ARQ_H

#include <stdint.h>

#include "proto/link_arq.h"

struct board_arq {
    struct link_arq_store tx; /* our numbered frames, kept for resending */
    struct link_arq_rx rx;    /* the board's frames, taken in seq order */
    struct link_arq_nak nak;  /* our NAKs' rate limit and give-up count */
    long long heard_ms;       /* when the last good frame came */
    long long byte_ms;        /* when the last byte came */
    int armed;                /* the link was seen damaged: poll when silent */
    int damage_seen;          /* the link was ever seen damaged (stall rule) */
    int gap;                  /* a board frame we lack is asked for */
    int polls;                /* polls in a row with no frame heard */
    int naks_heard;           /* 1: the board's NAKs name our numbering (0 while a
                                 session on a board left running opens: a NAK
                                 then may name an earlier session's seq) */
    int writing;              /* inside a frame's write: NAKs and resends wait */
    int resend_due;           /* a resend from resend_from waits for the write */
    uint16_t resend_from;
    int nak_due;              /* a NAK (flags nak_flags) waits for the write */
    uint8_t nak_flags;
    uint16_t asked_from;      /* the seq the board's NAKs last named */
    int asked;                /* NAKs in a row for it (LINK_ARQ_MAX_ASKS) */
};

#endif
