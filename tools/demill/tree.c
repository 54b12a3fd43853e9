/* tree.c: YAML into a tree of nodes with their lines (libyaml's event
 * parser), dotted-path overrides and writing the tree back (tree.h). */
#define _POSIX_C_SOURCE 200809L /* strtok_r */
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include <yaml.h>

#include "tree.h"

#define MAX_DEPTH 64

static char *dup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = malloc(n);
    return d ? memcpy(d, s, n) : NULL;
}

static void say(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
}

static tree *node_new(tree_kind kind, const char *src, int line)
{
    tree *t = calloc(1, sizeof *t);
    if (t) {
        t->kind = kind;
        t->src = src;
        t->line = line;
    }
    return t;
}

void tree_free(tree *t)
{
    if (!t)
        return;
    for (size_t k = 0; k < t->n; k++)
        tree_free(t->kid[k]);
    free(t->kid);
    free(t->key);
    free(t->text);
    free(t);
}

static int add_kid(tree *p, tree *c)
{
    if (p->n == p->cap) {
        size_t cap = p->cap ? 2 * p->cap : 4;
        tree **k = realloc(p->kid, cap * sizeof *k);
        if (!k)
            return -1;
        p->kid = k;
        p->cap = cap;
    }
    p->kid[p->n++] = c;
    return 0;
}

tree *tree_get(const tree *map, const char *key)
{
    if (!map || map->kind != TREE_MAP)
        return NULL;
    for (size_t k = 0; k < map->n; k++)
        if (!strcmp(map->kid[k]->key, key))
            return map->kid[k];
    return NULL;
}

/* an event with an anchor or an explicit tag */
static int decorated(const yaml_event_t *e)
{
    switch (e->type) {
    case YAML_SCALAR_EVENT:
        return e->data.scalar.anchor || (e->data.scalar.tag && !e->data.scalar.plain_implicit &&
                                         !e->data.scalar.quoted_implicit);
    case YAML_MAPPING_START_EVENT:
        return e->data.mapping_start.anchor || (e->data.mapping_start.tag && !e->data.mapping_start.implicit);
    case YAML_SEQUENCE_START_EVENT:
        return e->data.sequence_start.anchor || (e->data.sequence_start.tag && !e->data.sequence_start.implicit);
    default:
        return 0;
    }
}

int tree_parse(const char *src, const unsigned char *buf, size_t len, tree **out, char *err,
               size_t errlen)
{
    yaml_parser_t p;
    yaml_event_t e;
    if (!yaml_parser_initialize(&p)) {
        say(err, errlen, "%s: out of memory", src);
        return -1;
    }
    yaml_parser_set_input_string(&p, buf, len);
    tree *stack[MAX_DEPTH], *root = NULL;
    int depth = 0, docs = 0, rc = -1;
    char *pending_key = NULL; /* a map's key waiting for its value */
    int pending_line = 0;
    for (;;) {
        if (!yaml_parser_parse(&p, &e)) {
            say(err, errlen, "%s:%lu: %s", src, (unsigned long)p.problem_mark.line + 1,
                p.problem ? p.problem : "not YAML");
            goto done;
        }
        const int line = (int)e.start_mark.line + 1;
        const yaml_event_type_t type = e.type;
        if (type == YAML_STREAM_END_EVENT) {
            yaml_event_delete(&e);
            break;
        }
        if (type == YAML_DOCUMENT_START_EVENT && ++docs > 1) {
            say(err, errlen, "%s:%d: one document per file, found a second", src, line);
            yaml_event_delete(&e);
            goto done;
        }
        if (type == YAML_ALIAS_EVENT || decorated(&e)) {
            say(err, errlen, "%s:%d: anchors, aliases and tags are not allowed in a scene file",
                src, line);
            yaml_event_delete(&e);
            goto done;
        }
        tree *parent = depth ? stack[depth - 1] : NULL;
        if (type == YAML_SCALAR_EVENT && parent && parent->kind == TREE_MAP && !pending_key) {
            const char *k = (const char *)e.data.scalar.value;
            if (tree_get(parent, k)) {
                say(err, errlen, "%s:%d: key '%s' given twice", src, line, k);
                yaml_event_delete(&e);
                goto done;
            }
            if (!(pending_key = dup(k))) {
                yaml_event_delete(&e);
                goto done;
            }
            pending_line = line;
            yaml_event_delete(&e);
            continue;
        }
        if (parent && parent->kind == TREE_MAP && !pending_key &&
            (type == YAML_MAPPING_START_EVENT || type == YAML_SEQUENCE_START_EVENT)) {
            say(err, errlen, "%s:%d: a key must be a name, not a %s", src, line,
                type == YAML_MAPPING_START_EVENT ? "map" : "list");
            yaml_event_delete(&e);
            goto done;
        }
        tree *node = NULL;
        if (type == YAML_SCALAR_EVENT) {
            node = node_new(TREE_SCALAR, src, line);
            if (node && !(node->text = dup((const char *)e.data.scalar.value))) {
                free(node);
                node = NULL;
            }
            if (node)
                node->quoted = e.data.scalar.style != YAML_PLAIN_SCALAR_STYLE;
        } else if (type == YAML_MAPPING_START_EVENT || type == YAML_SEQUENCE_START_EVENT) {
            if (depth == MAX_DEPTH) {
                say(err, errlen, "%s:%d: nested deeper than %d levels", src, line, MAX_DEPTH);
                yaml_event_delete(&e);
                goto done;
            }
            node = node_new(type == YAML_MAPPING_START_EVENT ? TREE_MAP : TREE_SEQ, src, line);
        } else if (type == YAML_MAPPING_END_EVENT || type == YAML_SEQUENCE_END_EVENT) {
            depth--;
            yaml_event_delete(&e);
            continue;
        } else {
            yaml_event_delete(&e);
            continue;
        }
        yaml_event_delete(&e);
        if (!node) {
            say(err, errlen, "%s: out of memory", src);
            goto done;
        }
        if (parent) {
            if (parent->kind == TREE_MAP) {
                node->key = pending_key;
                node->line = pending_line;
                pending_key = NULL;
            }
            if (add_kid(parent, node)) {
                tree_free(node);
                say(err, errlen, "%s: out of memory", src);
                goto done;
            }
        } else {
            root = node;
        }
        if (node->kind != TREE_SCALAR)
            stack[depth++] = node;
    }
    if (!root)
        root = node_new(TREE_MAP, src, 1); /* an empty file: an empty map */
    rc = root ? 0 : -1;
    if (rc)
        say(err, errlen, "%s: out of memory", src);
done:
    free(pending_key);
    yaml_parser_delete(&p);
    if (rc)
        tree_free(root);
    else
        *out = root;
    return rc;
}

int tree_parse_file(const char *path, tree **out, char *err, size_t errlen)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        say(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    unsigned char *b = NULL;
    size_t n = 0, cap = 0, got;
    do {
        if (n == cap) {
            unsigned char *nb = realloc(b, cap = 2 * cap + 4096);
            if (!nb) {
                free(b);
                fclose(f);
                say(err, errlen, "%s: out of memory", path);
                return -1;
            }
            b = nb;
        }
        got = fread(b + n, 1, cap - n, f);
        n += got;
    } while (got);
    const int bad = ferror(f);
    fclose(f);
    if (bad) {
        free(b);
        say(err, errlen, "%s: cannot read", path);
        return -1;
    }
    const int rc = tree_parse(path, b, n, out, err, errlen);
    free(b);
    return rc;
}

static void mark_set(tree *t)
{
    t->line = 0;
    for (size_t k = 0; k < t->n; k++)
        mark_set(t->kid[k]);
}

int tree_set(tree *root, const char *path, const char *value, char *err, size_t errlen)
{
    tree *v;
    if (tree_parse("--set", (const unsigned char *)value, strlen(value), &v, err, errlen))
        return -1;
    /* an empty value parses as an empty map: take it as an empty string */
    if (v->kind == TREE_MAP && v->n == 0 && !*value) {
        v->kind = TREE_SCALAR;
        v->text = dup("");
    }
    mark_set(v);
    char *p = dup(path), *save = NULL;
    if (!p) {
        tree_free(v);
        say(err, errlen, "out of memory");
        return -1;
    }
    tree *at = root;
    for (char *part = strtok_r(p, ".", &save); part; part = strtok_r(NULL, ".", &save)) {
        const int last = !save || !*save;
        tree *next = NULL;
        size_t idx = 0;
        if (at->kind == TREE_MAP) {
            next = tree_get(at, part);
            if (!next && last) {
                if (!(v->key = dup(part)) || add_kid(at, v)) {
                    say(err, errlen, "out of memory");
                    break;
                }
                free(p);
                return 0;
            }
            if (next)
                for (idx = 0; at->kid[idx] != next; idx++)
                    ;
        } else if (at->kind == TREE_SEQ) {
            char *end;
            const unsigned long k = strtoul(part, &end, 10);
            if (*end || end == part || k >= at->n) {
                say(err, errlen, "--set %s: '%s' is not an item of the list (0 to %zu)", path,
                    part, at->n ? at->n - 1 : 0);
                break;
            }
            next = at->kid[idx = k];
        }
        if (!next) {
            say(err, errlen, "--set %s: no entry '%s' in the scene", path, part);
            break;
        }
        if (last) {
            v->key = next->key;
            next->key = NULL;
            at->kid[idx] = v;
            tree_free(next);
            free(p);
            return 0;
        }
        at = next;
    }
    free(p);
    tree_free(v);
    return -1;
}

/* a scalar that reads back as itself without quotes */
static int plain_ok(const char *s)
{
    if (!*s || strpbrk(s, ":#,[]{}&*!|>'\"%@`\n\t") || s[0] == '-' || s[0] == ' ' ||
        s[0] == '?' || s[strlen(s) - 1] == ' ')
        return (s[0] == '-' && s[1] && strspn(s + 1, "0123456789.eE+-") == strlen(s + 1));
    return 1;
}

static int write_scalar(FILE *f, const tree *t)
{
    if (!t->quoted && plain_ok(t->text))
        return fprintf(f, "%s", t->text) < 0;
    fputc('"', f);
    for (const char *c = t->text; *c; c++) {
        if (*c == '"' || *c == '\\')
            fputc('\\', f);
        if (*c == '\n')
            fputs("\\n", f);
        else
            fputc(*c, f);
    }
    return fputc('"', f) == EOF;
}

static int flat(const tree *t)
{
    for (size_t k = 0; k < t->n; k++)
        if (t->kid[k]->kind != TREE_SCALAR && (t->kid[k]->kind != TREE_SEQ || !flat(t->kid[k])))
            return 0;
    return t->kind == TREE_SEQ;
}

static void write_flow(FILE *f, const tree *t)
{
    if (t->kind == TREE_SCALAR) {
        write_scalar(f, t);
        return;
    }
    fputc('[', f);
    for (size_t k = 0; k < t->n; k++) {
        if (k)
            fputs(", ", f);
        write_flow(f, t->kid[k]);
    }
    fputc(']', f);
}

static void write_node(FILE *f, const tree *t, int indent)
{
    for (size_t k = 0; k < t->n; k++) {
        const tree *c = t->kid[k];
        fprintf(f, "%*s", indent, "");
        if (t->kind == TREE_MAP) {
            tree key = {.kind = TREE_SCALAR, .text = c->key};
            write_scalar(f, &key);
            fputc(':', f);
        } else {
            fputc('-', f);
        }
        if (c->kind == TREE_SCALAR || flat(c) || c->n == 0) {
            fputc(' ', f);
            if (c->kind == TREE_MAP)
                fputs("{}", f);
            else
                write_flow(f, c);
            fputc('\n', f);
        } else {
            fputc('\n', f);
            write_node(f, c, indent + 2);
        }
    }
}

int tree_write(FILE *f, const tree *t)
{
    if (t->kind == TREE_SCALAR || flat(t)) {
        write_flow(f, t);
        fputc('\n', f);
    } else {
        write_node(f, t, 0);
    }
    return ferror(f) ? -1 : 0;
}

static int find_path(const tree *at, const tree *node, char *buf, size_t len)
{
    if (at == node)
        return 1;
    for (size_t k = 0; k < at->n; k++) {
        const size_t used = strlen(buf);
        if (at->kind == TREE_MAP)
            snprintf(buf + used, len - used, "%s%s", used ? "." : "", at->kid[k]->key);
        else
            snprintf(buf + used, len - used, "%s%zu", used ? "." : "", k);
        if (find_path(at->kid[k], node, buf, len))
            return 1;
        buf[used] = '\0';
    }
    return 0;
}

void tree_path(const tree *root, const tree *node, char *buf, size_t len)
{
    buf[0] = '\0';
    if (!find_path(root, node, buf, len))
        buf[0] = '\0';
}
