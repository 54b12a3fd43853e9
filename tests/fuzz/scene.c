/* scene.c: the fuzz target of the scene-file reader of the demill program
 * (tools/demill/tree.c and scene.c).
 *
 * An input is a scene file's bytes. It is parsed (tree_parse), written back
 * as YAML (tree_write) and parsed again, and checked as a scene
 * (scene_build in SCENE_CHECK mode: every section checked, materials, pairs
 * and the drum built in a world, no particles or walls added, nothing
 * run). Every parse and check must succeed or fail with a message that
 * names the input ("fuzz:LINE: ..." or "--set ..."), never crash, leak or
 * touch memory it should not (run under AddressSanitizer and UBSan); a tree
 * that parsed must parse again from its own YAML with the same shape; a
 * failed check leaves no world.
 *
 * Built two ways, as the other targets are: with clang's libFuzzer
 * (tests/fuzz/run scene) and with a plain main() (replay.c), which CTest
 * runs on the committed corpus in tests/fuzz/corpus-scene/. */
#define _POSIX_C_SOURCE 200809L /* open_memstream */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int same_shape(const tree *a, const tree *b)
{
    if (a->kind != b->kind || a->n != b->n)
        return 0;
    if ((a->key || b->key) && (!a->key || !b->key || strcmp(a->key, b->key)))
        return 0;
    if (a->kind == TREE_SCALAR && strcmp(a->text, b->text))
        return 0;
    for (size_t k = 0; k < a->n; k++)
        if (!same_shape(a->kid[k], b->kid[k]))
            return 0;
    return 1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char err[1024] = "";
    tree *t;
    if (tree_parse("fuzz", data, size, &t, err, sizeof err)) {
        if (strncmp(err, "fuzz", 4))
            abort();
        return 0;
    }
    char *yaml = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&yaml, &len);
    if (!f || tree_write(f, t))
        abort();
    fclose(f);
    tree *again;
    if (tree_parse("fuzz-again", (const unsigned char *)yaml, len, &again, err, sizeof err)) {
        fprintf(stderr, "written back, the tree does not parse: %s\n%s", err, yaml);
        abort();
    }
    if (!same_shape(t, again)) {
        fprintf(stderr, "written back, the tree changed:\n%s", yaml);
        abort();
    }
    tree_free(again);
    free(yaml);
    scene s = {0};
    if (scene_build(&s, t, ".", SCENE_CHECK, err, sizeof err)) {
        if (s.w || (strncmp(err, "fuzz", 4) && strncmp(err, "--set", 5)))
            abort();
    } else {
        demill_world_destroy(s.w);
    }
    tree_free(t);
    return 0;
}
