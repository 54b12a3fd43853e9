/* tree.h: a YAML document as a tree of maps, sequences and scalars that
 * remembers where each node came from (file and line), read with libyaml;
 * dotted-path overrides (--set) and writing the tree back as YAML. */
#ifndef DEMILL_TREE_H
#define DEMILL_TREE_H

#include <stddef.h>
#include <stdio.h>

typedef enum tree_kind { TREE_SCALAR, TREE_MAP, TREE_SEQ } tree_kind;

typedef struct tree {
    tree_kind kind;
    const char *src;   /* the file (or "--set") it came from; owned by the caller */
    int line;          /* 1-based line; 0 for a --set value */
    char *key;         /* the key of a map entry, else NULL */
    char *text;        /* a scalar's text */
    struct tree **kid; /* a map's entries or a sequence's items */
    size_t n, cap;
    int quoted;        /* a scalar written in quotes: always a string */
} tree;

/* Parses one YAML document (len bytes) into *out. src names it in the
 * nodes and in messages. Anchors, aliases, tags and several documents are
 * refused. 0, or -1 with "src:line: message" in err. */
int tree_parse(const char *src, const unsigned char *buf, size_t len, tree **out, char *err,
               size_t errlen);

/* Reads and parses a file (tree_parse with src = path). */
int tree_parse_file(const char *path, tree **out, char *err, size_t errlen);

void tree_free(tree *t);

/* The entry `key` of a map, or NULL. */
tree *tree_get(const tree *map, const char *key);

/* Replaces (or adds, in a map) the node at a dotted path (a number indexes
 * a sequence) with `value`, parsed as YAML (so "[1, 2]" is a sequence).
 * Every map or sequence on the path but the last must exist. 0, or -1 with
 * a message. */
int tree_set(tree *root, const char *path, const char *value, char *err, size_t errlen);

/* Writes the tree as YAML (block maps and sequences, scalars quoted where
 * needed). 0, or -1 on a write error. */
int tree_write(FILE *f, const tree *t);

/* The dotted path of a node within root ("materials.steel.density"), into
 * buf; "" for root itself or a node not in it. */
void tree_path(const tree *root, const tree *node, char *buf, size_t len);

#endif
