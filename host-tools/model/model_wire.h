/* model_wire.h: a struct model (model.h) as bytes, so a child process that
 * read a model file with the model library can hand it to its parent
 * (model_child.c).  Both ends are the same program: numbers go in the
 * machine's own layout.  The reader trusts nothing: every count is checked
 * against the bytes that are there, every index against what it indexes,
 * every name for its end, before anything is allocated or used. */
#ifndef LINKS1_HOST_SCENE_MODEL_WIRE_H
#define LINKS1_HOST_SCENE_MODEL_WIRE_H

#include <stddef.h>

#include "host-tools/model/model.h"

/* Writes m to the descriptor fd (no stdio: safe in a child of a program
 * with threads).  0, or -1 when a write failed. */
int model_wire_send(int fd, const struct model *m);

/* Reads the len bytes at buf, all of one model_wire_send, into *m.  0, or
 * -1 with what is wrong in why and *m empty. */
int model_wire_take(const void *buf, size_t len, struct model *m, char *why, size_t whylen);

#endif
