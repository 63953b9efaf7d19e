/*
 * A compiled prototype of moos-lint's mission front end, for measurement only.
 *
 * It does the work of frontends/nsplug.py and frontends/parsers/moos.py on a
 * mission file, in C: read the file, split its lines (LF, CRLF, bare CR),
 * follow `#include "file"` (the includer's folder), keep `#define NAME value`,
 * take `#ifdef` / `#ifndef` / `#else` / `#endif`, substitute `$(NAME)` and
 * `%(NAME)`, then read the expanded lines as a .moos file: `ProcessConfig =
 * NAME` blocks in braces, `key = value` parameters, `//` comments. It returns
 * Python objects as the real front end must: one (text, path, line) tuple per
 * expanded line and one (block, key, value, line) tuple per parameter.
 *
 * It is not moos-lint's front end (no source map of include chains, no
 * problems reported, no launch-script include paths): it shows what a compiled
 * front end would cost. `python scripts/prototype/measure.py TREE` builds it
 * and compares it with the Python front end on the same files.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_DEPTH 16
#define MAX_DEFS 256

typedef struct { char name[64]; char value[256]; } Def;
typedef struct { Def defs[MAX_DEFS]; int n; } Defs;

static char *read_file(const char *path, long *len) {
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *buf = malloc(n + 1);
    if (!buf) { fclose(f); return NULL; }
    *len = (long)fread(buf, 1, n, f);
    buf[*len] = 0;
    fclose(f);
    return buf;
}

static const char *lookup(Defs *d, const char *name, size_t len) {
    for (int i = 0; i < d->n; i++)
        if (strlen(d->defs[i].name) == len && !strncmp(d->defs[i].name, name, len))
            return d->defs[i].value;
    return NULL;
}

static void define(Defs *d, const char *rest) {
    while (*rest == ' ' || *rest == '\t') rest++;
    const char *e = rest;
    while (*e && *e != ' ' && *e != '\t') e++;
    if (e == rest || d->n >= MAX_DEFS) return;
    Def *x = &d->defs[d->n++];
    snprintf(x->name, sizeof x->name, "%.*s", (int)(e - rest), rest);
    while (*e == ' ' || *e == '\t') e++;
    snprintf(x->value, sizeof x->value, "%s", e);
}

/* $(NAME) and %(NAME) substituted into out (at most cap bytes). */
static void substitute(Defs *d, const char *s, size_t n, char *out, size_t cap) {
    size_t o = 0;
    for (size_t i = 0; i < n && o + 1 < cap;) {
        if ((s[i] == '$' || s[i] == '%') && i + 1 < n && s[i + 1] == '(') {
            const char *close = memchr(s + i + 2, ')', n - i - 2);
            if (close) {
                const char *v = lookup(d, s + i + 2, close - (s + i + 2));
                if (v) {
                    size_t vl = strlen(v);
                    if (o + vl >= cap) vl = cap - o - 1;
                    memcpy(out + o, v, vl);
                    o += vl;
                    i = close - s + 1;
                    continue;
                }
            }
        }
        out[o++] = s[i++];
    }
    out[o] = 0;
}

typedef struct {
    PyObject *lines, *params;
    char block[128];
    int in_block;
} Out;

static void trim(const char **b, const char **e) {
    while (*b < *e && isspace((unsigned char)**b)) (*b)++;
    while (*e > *b && isspace((unsigned char)(*e)[-1])) (*e)--;
}

static int moos_line(Out *out, const char *t, PyObject *path, long lineno) {
    const char *b = t, *e = t + strlen(t);
    const char *c = strstr(t, "//");
    if (c) e = c;
    trim(&b, &e);
    if (b == e) return 0;
    if (*b == '{') return 0;
    if (*b == '}') { out->in_block = 0; return 0; }
    const char *eq = memchr(b, '=', e - b);
    if (!eq) return 0;
    const char *kb = b, *ke = eq, *vb = eq + 1, *ve = e;
    trim(&kb, &ke);
    trim(&vb, &ve);
    if ((size_t)(ke - kb) == 13 && !strncasecmp(kb, "ProcessConfig", 13)) {
        snprintf(out->block, sizeof out->block, "%.*s", (int)(ve - vb), vb);
        out->in_block = 1;
        return 0;
    }
    PyObject *p = Py_BuildValue("(s#s#s#l)", out->in_block ? out->block : "", (Py_ssize_t)(out->in_block ? strlen(out->block) : 0),
                                kb, (Py_ssize_t)(ke - kb), vb, (Py_ssize_t)(ve - vb), lineno);
    if (!p) return -1;
    int r = PyList_Append(out->params, p);
    Py_DECREF(p);
    (void)path;
    return r;
}

static int expand(const char *path, Defs *d, Out *out, int depth) {
    if (depth > MAX_DEPTH) return 0;
    long len = 0;
    char *buf = read_file(path, &len);
    if (!buf) return 0;
    PyObject *py_path = PyUnicode_FromString(path);
    if (!py_path) { free(buf); return -1; }
    int skip[MAX_DEPTH * 4], top = 0, skipping = 0;
    char line[8192];
    long lineno = 0;
    for (long i = 0; i <= len;) {
        long j = i;
        while (j < len && buf[j] != '\n' && buf[j] != '\r') j++;
        long n = j - i;
        const char *s = buf + i;
        lineno++;
        const char *t = s;
        while (t < s + n && (*t == ' ' || *t == '\t')) t++;
        if (t < s + n && *t == '#') {
            char dir[16] = {0};
            const char *w = t;
            while (w < s + n && !isspace((unsigned char)*w) && w - t < 15) w++;
            memcpy(dir, t, w - t);
            char rest[1024];
            snprintf(rest, sizeof rest, "%.*s", (int)(s + n - w), w);
            if (!strcmp(dir, "#ifdef") || !strcmp(dir, "#ifndef")) {
                char *r = rest; while (*r == ' ' || *r == '\t') r++;
                char *re = r; while (*re && !isspace((unsigned char)*re)) re++;
                int has = lookup(d, r, re - r) != NULL;
                int take = dir[3] == 'd' ? has : !has;
                if (top < MAX_DEPTH * 4) skip[top++] = skipping;
                skipping = skipping || !take;
            } else if (!strcmp(dir, "#else")) {
                if (top) skipping = skip[top - 1] || !skipping;
            } else if (!strcmp(dir, "#endif")) {
                if (top) skipping = skip[--top];
            } else if (!skipping && !strcmp(dir, "#define")) {
                define(d, rest);
            } else if (!skipping && !strcmp(dir, "#include")) {
                char *q = strchr(rest, '"');
                char *q2 = q ? strchr(q + 1, '"') : NULL;
                if (q && q2) {
                    char child[4096];
                    const char *slash = strrchr(path, '/');
                    int dl = slash ? (int)(slash - path) : 1;
                    snprintf(child, sizeof child, "%.*s/%.*s", dl, slash ? path : ".", (int)(q2 - q - 1), q + 1);
                    if (expand(child, d, out, depth + 1) < 0) { Py_DECREF(py_path); free(buf); return -1; }
                }
            }
        } else if (!skipping) {
            substitute(d, s, (size_t)n, line, sizeof line);
            PyObject *tup = Py_BuildValue("(sOl)", line, py_path, lineno);
            if (!tup || PyList_Append(out->lines, tup) < 0) { Py_XDECREF(tup); Py_DECREF(py_path); free(buf); return -1; }
            Py_DECREF(tup);
            if (moos_line(out, line, py_path, lineno) < 0) { Py_DECREF(py_path); free(buf); return -1; }
        }
        if (j < len && buf[j] == '\r' && j + 1 < len && buf[j + 1] == '\n') j++;
        i = j + 1;
    }
    Py_DECREF(py_path);
    free(buf);
    return 0;
}

static PyObject *expand_moos(PyObject *self, PyObject *args) {
    const char *path;
    if (!PyArg_ParseTuple(args, "s", &path)) return NULL;
    Out out = {PyList_New(0), PyList_New(0), {0}, 0};
    Defs *d = calloc(1, sizeof(Defs));
    if (!out.lines || !out.params || !d) { free(d); return PyErr_NoMemory(); }
    int r = expand(path, d, &out, 0);
    free(d);
    if (r < 0) { Py_DECREF(out.lines); Py_DECREF(out.params); return NULL; }
    return Py_BuildValue("(NN)", out.lines, out.params);
}

static PyMethodDef methods[] = {
    {"expand_moos", expand_moos, METH_VARARGS, "(lines, params) of one mission file"},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "frontend_prototype", NULL, -1, methods};

PyMODINIT_FUNC PyInit_frontend_prototype(void) { return PyModule_Create(&module); }
