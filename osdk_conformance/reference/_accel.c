/*
 * osdk_conformance.reference._accel - the native decoder of `osdkc decode` and the
 * Python API: the generated C decoder (generated/c: deframer, frame and
 * payload decoders, tables) and its value model as Python objects
 * (generated/cpython), behind the same event stream the pure-Python
 * reference (osdk_conformance/reference/decode.py) produces.
 *
 * The events are the reference's, key for key and in the same order
 * (docs/VALUE-MODEL.md, "`osdkc decode` output"): the receiver, the frame
 * and payload decoding and the ACK matching follow conformance/PROTOCOL.md,
 * and the conformance suite replays every vector against this module as its
 * own implementation ("c-accel"). Only the wording of `detail`, which is
 * for people, is the C decoder's.
 *
 * Loaded through osdk_conformance/reference/accel.py, which decides whether
 * it is used (OSDKC_ACCEL). The GIL is held throughout: a decoder object
 * must not be fed from two threads at once (the Python one must not either).
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include <string.h>

#include "osdk_acks.h"
#include "osdk_columns.h"
#include "osdk_decoder.h"
#include "osdk_deframer.h"
#include "osdk_model_py.h"
#include "osdk_tables.h"

static PyObject *DecodeError;

/* Event keys and the fixed strings of events, interned once. */
enum {
    K_OFFSET, K_KIND, K_COMMAND, K_ACK_OF, K_ACK, K_FRAME, K_ERROR, K_DETAIL, K_LENGTH, K_FRAME_HEADER,
    K_DIRECTION, K_BODY, S_FRAME, S_ERROR, S_GARBAGE, S_NONE, S_ENCRYPTED, S_ACK, TEXT_COUNT
};
static const char *const text_values[TEXT_COUNT] = {
    "offset", "kind", "command", "ack_of", "ack", "frame", "error", "detail", "length", "frame_header",
    "direction", "body", "frame", "error", "garbage", "none", "encrypted", "ack",
};
static PyObject *text[TEXT_COUNT];

/* ---- the Decoder type ------------------------------------------------------------------------- */

#define CHANNELS 2 /* rx and tx of a capture: one deframer each, one set of ACK slots */

typedef struct {
    PyObject_HEAD
    uint8_t profile;
    PyObject *header_fields; /* the reference's header_fields(raw) for frames that do not decode */
    osdk_acks_t acks;        /* one slot per session 2..31, for both directions: an ACK received answers a command sent */
    osdk_deframer_t deframer[CHANNELS];
    uint8_t window[CHANNELS][OSDK_DEFRAMER_MIN_BUFFER];
    osdk_frame_t frame;
    osdk_payload_t payload;
    /* during one feed/finish */
    PyObject *out;       /* the list of events */
    PyObject *direction; /* borrowed; NULL when events carry no direction */
    bool failed;         /* a Python error is set; the rest of the events are dropped */
    bool busy;           /* inside feed/finish: header_fields may run Python code that calls back */
} Decoder;

static PyObject *new_event(Decoder *self, Py_ssize_t size, uint64_t offset, PyObject *kind)
{
    PyObject *ev = OSDK_PY_NEW_DICT(size + (self->direction ? 1 : 0));
    if (ev == NULL) return NULL;
    if ((self->direction && PyDict_SetItem(ev, text[K_DIRECTION], self->direction) < 0) ||
        osdk_py_put(ev, text[K_OFFSET], PyLong_FromUnsignedLongLong(offset)) < 0 ||
        PyDict_SetItem(ev, text[K_KIND], kind) < 0) {
        Py_DECREF(ev);
        return NULL;
    }
    return ev;
}

static PyObject *detail_of(const osdk_error_t *err)
{
    return PyUnicode_FromFormat("%s.%s failed at offset %zu", err->type ? err->type : "?",
                                err->field ? err->field : "?", err->offset);
}

/* A frame whose value did not decode: the whole frame is one error event. */
static PyObject *frame_error(Decoder *self, const osdk_event_t *ev, const osdk_error_t *err, const char *ack_of)
{
    PyObject *e = new_event(self, 7, ev->offset, text[S_ERROR]);
    if (e == NULL) return NULL;
    if (osdk_py_put(e, text[K_ERROR], osdk_py_name(osdk_status_name(err->status))) < 0 ||
        osdk_py_put(e, text[K_DETAIL], detail_of(err)) < 0 ||
        osdk_py_put(e, text[K_LENGTH], PyLong_FromSize_t(ev->length)) < 0 ||
        osdk_py_put(e, text[K_FRAME_HEADER],
                    PyObject_CallFunction(self->header_fields, "y#", (const char *)ev->raw, (Py_ssize_t)ev->length)) < 0 ||
        (ack_of && osdk_py_put(e, text[K_ACK_OF], osdk_py_name(ack_of)) < 0)) {
        Py_DECREF(e);
        return NULL;
    }
    return e;
}

static PyObject *frame_event(Decoder *self, const osdk_event_t *ev)
{
    osdk_error_t err;
    osdk_frame_t *f = &self->frame;
    const char *command = NULL, *ack_of = NULL;
    bool have_ack = false;
    PyObject *e, *model;
    osdk_error_clear(&err);
    if (osdk_frame_decode(ev->raw, ev->length, self->profile, f, &err) != OSDK_OK)
        return frame_error(self, ev, &err, NULL);
    {
        bool header_only = f->len == OSDK_FRAME_HEADER_LEN;
        bool plain = f->data_present && f->data.tag == OSDK_FRAME_DATA_FRAME_DATA;
        uint8_t cmd_set, cmd_id;
        if (f->is_ack && (plain || header_only) &&
            osdk_acks_take(&self->acks, f->session, f->seq, &cmd_set, &cmd_id)) {
            /* a header-only ACK is matched too: its value is empty */
            const uint8_t *value = plain ? f->data.u.frame_data.ack_value.ptr : ev->raw + OSDK_FRAME_HEADER_LEN;
            size_t value_len = plain ? f->data.u.frame_data.ack_value.len : 0;
            ack_of = osdk_command_name(cmd_set, cmd_id);
            if (osdk_payload_decode(value, value_len, cmd_set, cmd_id, true, self->profile, &self->payload, &err) != OSDK_OK)
                return frame_error(self, ev, &err, ack_of);
            have_ack = true;
        } else if (header_only) {
            command = "none";
        } else if (!plain) {
            command = "encrypted";
        } else if (f->is_ack) {
            command = "ack";
        } else {
            const osdk_frame_frame_data_t *fd = &f->data.u.frame_data;
            command = osdk_command_name(fd->cmd_set, fd->cmd_id);
            osdk_acks_command(&self->acks, f->session, f->seq, fd->cmd_set, fd->cmd_id);
        }
    }
    e = new_event(self, 5, ev->offset, text[S_FRAME]);
    if (e == NULL) return NULL;
    if (command && osdk_py_put(e, text[K_COMMAND], osdk_py_name(command)) < 0) goto fail;
    if (ack_of && osdk_py_put(e, text[K_ACK_OF], osdk_py_name(ack_of)) < 0) goto fail;
    if (have_ack) {
        PyObject *body;
        model = osdk_payload_to_py(&self->payload);
        if (model == NULL) goto fail;
        body = PyDict_GetItemWithError(model, text[K_BODY]);
        if (body == NULL) {
            if (!PyErr_Occurred()) PyErr_SetString(PyExc_SystemError, "an ACK value without a body");
            Py_DECREF(model);
            goto fail;
        }
        if (PyDict_SetItem(e, text[K_ACK], body) < 0) {
            Py_DECREF(model);
            goto fail;
        }
        Py_DECREF(model);
    }
    if (osdk_py_put(e, text[K_FRAME], osdk_frame_to_py(f)) < 0) goto fail;
    return e;
fail:
    Py_DECREF(e);
    return NULL;
}

static void on_event(void *user, const osdk_event_t *ev)
{
    Decoder *self = user;
    PyObject *e = NULL;
    if (self->failed) return;
    switch (ev->kind) {
    case OSDK_EVENT_FRAME:
        e = frame_event(self, ev);
        break;
    case OSDK_EVENT_GARBAGE:
        e = new_event(self, 3, ev->offset, text[S_GARBAGE]);
        if (e && osdk_py_put(e, text[K_LENGTH], PyLong_FromSize_t(ev->length)) < 0) Py_CLEAR(e);
        break;
    case OSDK_EVENT_ERROR:
    default:
        e = new_event(self, 5, ev->offset, text[S_ERROR]);
        if (e && (osdk_py_put(e, text[K_ERROR], osdk_py_name(osdk_status_name(ev->error))) < 0 ||
                  osdk_py_put(e, text[K_DETAIL], PyUnicode_FromString(ev->detail ? ev->detail : "")) < 0 ||
                  osdk_py_put(e, text[K_LENGTH], PyLong_FromSize_t(ev->length)) < 0))
            Py_CLEAR(e);
        break;
    }
    if (e == NULL || PyList_Append(self->out, osdk_py_untracked(e)) < 0) self->failed = true;
    Py_XDECREF(e);
}

/* The channel of a direction: None and "rx" are 0, "tx" is 1. */
static int channel_of(PyObject *direction, PyObject **tag)
{
    *tag = NULL;
    if (direction == NULL || direction == Py_None) return 0;
    if (PyUnicode_Check(direction)) {
        *tag = direction;
        if (PyUnicode_CompareWithASCIIString(direction, "rx") == 0) return 0;
        if (PyUnicode_CompareWithASCIIString(direction, "tx") == 0) return 1;
    }
    PyErr_SetString(PyExc_ValueError, "direction must be None, 'rx' or 'tx'");
    return -1;
}

static PyObject *run(Decoder *self, PyObject *direction, const uint8_t *data, size_t len, bool finish)
{
    PyObject *out;
    int ch;
    if (self->header_fields == NULL) {
        PyErr_SetString(PyExc_RuntimeError, "Decoder.__init__ was not called");
        return NULL;
    }
    if (self->busy) { /* the deframer must not be fed from inside its own callback */
        PyErr_SetString(PyExc_RuntimeError, "this Decoder is already decoding (a call from inside it, or "
                                            "from another thread)");
        return NULL;
    }
    ch = channel_of(direction, &self->direction);
    if (ch < 0) return NULL;
    out = PyList_New(0);
    if (out == NULL) return NULL;
    self->out = out;
    self->failed = false;
    self->busy = true;
    if (finish) osdk_deframer_finish(&self->deframer[ch], on_event, self);
    else osdk_deframer_feed(&self->deframer[ch], data, len, on_event, self);
    self->busy = false;
    self->out = NULL;
    self->direction = NULL;
    if (self->failed) {
        Py_DECREF(out);
        return NULL;
    }
    return out;
}

static PyObject *Decoder_feed(Decoder *self, PyObject *args, PyObject *kwargs)
{
    static char *kwlist[] = {"data", "direction", NULL};
    Py_buffer buf;
    PyObject *direction = NULL, *out;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "y*|O:feed", kwlist, &buf, &direction)) return NULL;
    out = run(self, direction, buf.buf, (size_t)buf.len, false);
    PyBuffer_Release(&buf);
    return out;
}

static PyObject *Decoder_finish(Decoder *self, PyObject *args, PyObject *kwargs)
{
    static char *kwlist[] = {"direction", NULL};
    PyObject *direction = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "|O:finish", kwlist, &direction)) return NULL;
    return run(self, direction, NULL, 0, true);
}

static int Decoder_init(Decoder *self, PyObject *args, PyObject *kwargs)
{
    static char *kwlist[] = {"profile", "header_fields", NULL};
    unsigned char profile;
    PyObject *header_fields;
    int ch;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "bO:Decoder", kwlist, &profile, &header_fields))
        return -1;
    if (self->busy) {
        PyErr_SetString(PyExc_RuntimeError, "this Decoder is decoding");
        return -1;
    }
    if (!PyCallable_Check(header_fields)) {
        PyErr_SetString(PyExc_TypeError, "header_fields must be callable");
        return -1;
    }
    osdk_acks_init(&self->acks);
    self->profile = profile;
    Py_INCREF(header_fields);
    Py_XSETREF(self->header_fields, header_fields);
    for (ch = 0; ch < CHANNELS; ch++) osdk_deframer_init(&self->deframer[ch], self->window[ch], sizeof self->window[ch]);
    return 0;
}

/* header_fields is any callable, so a decoder can be part of a reference cycle. */
static int Decoder_traverse(Decoder *self, visitproc visit, void *arg)
{
    Py_VISIT(self->header_fields);
    return 0;
}

static int Decoder_clear(Decoder *self)
{
    Py_CLEAR(self->header_fields);
    return 0;
}

static void Decoder_dealloc(Decoder *self)
{
    PyObject_GC_UnTrack(self);
    Decoder_clear(self);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

static PyMethodDef Decoder_methods[] = {
    {"feed", (PyCFunction)(void (*)(void))Decoder_feed, METH_VARARGS | METH_KEYWORDS,
     "feed(data, direction=None) -> list of events completed by these bytes.\n"
     "direction 'rx' (the default channel) or 'tx' picks the receiver; a str direction is also put first in "
     "each event."},
    {"finish", (PyCFunction)(void (*)(void))Decoder_finish, METH_VARARGS | METH_KEYWORDS,
     "finish(direction=None) -> list of the events the end of the input leaves."},
    {NULL, NULL, 0, NULL},
};

static PyTypeObject DecoderType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "osdk_conformance.reference._accel.Decoder",
    .tp_basicsize = sizeof(Decoder),
    .tp_flags = Py_TPFLAGS_DEFAULT | Py_TPFLAGS_HAVE_GC,
    .tp_traverse = (traverseproc)Decoder_traverse,
    .tp_clear = (inquiry)Decoder_clear,
    .tp_doc = "Decoder(profile, header_fields): a stream of bytes -> the events of "
              "osdkc decode.\nprofile is the u8 value of the wire profile (spec/rules.yaml).",
    .tp_new = PyType_GenericNew,
    .tp_init = (initproc)Decoder_init,
    .tp_dealloc = (destructor)Decoder_dealloc,
    .tp_free = PyObject_GC_Del,
    .tp_methods = Decoder_methods,
};

/* ---- the Columns type: the broadcasts of a stream as typed columns ------------------------------ */

/*
 * One row per broadcast frame that decodes: each leaf of the profile's layout
 * (osdk_columns.h) in a bytearray of its element type with a bytearray of
 * presence bytes beside it, the frame's stream offset (uint64) and the
 * capture time of the bytes that completed it (int64 nanoseconds since the
 * Unix epoch; NO_TIME when the bytes came without one). The bytearrays are handed to Python as they are
 * (numpy and pyarrow wrap them without a copy); no object is made per
 * value. Every other event is only counted.
 */
/* What the stream held besides the rows. The events the end of the input
 * leaves (finish: a frame the recording stopped inside, and the receiver's
 * rescan of its bytes) are counted apart, as `osdkc decode` marks them
 * "capture_end" (reference/decode.py, mark_capture_end). */
enum { C_FRAMES, C_BROADCASTS, C_OTHER, C_ENCRYPTED, C_UNDECODABLE, C_ERRORS, C_GARBAGE_BYTES, C_CAPTURE_END,
       C_COUNT };
static const char *const count_names[C_COUNT] = {
    "frames", "broadcasts", "other_frames", "encrypted_frames", "undecodable_broadcasts", "errors",
    "garbage_bytes", "capture_end_events",
};

typedef struct {
    PyObject_HEAD
    uint8_t profile;
    const osdk_column_set_t *set;
    osdk_deframer_t deframer;
    uint8_t window[OSDK_DEFRAMER_MIN_BUFFER];
    osdk_frame_t frame;
    osdk_payload_t payload;
    size_t rows, cap;
    PyObject **data;   /* set->count bytearrays */
    PyObject **valid;  /* set->count bytearrays */
    void **data_at;    /* their buffers, valid until the next resize */
    uint8_t **valid_at;
    PyObject *offsets; /* uint64 per row */
    PyObject *times;   /* int64 per row */
    int64_t now;       /* the capture time of the bytes being fed, or NO_TIME */
    uint64_t counts[C_COUNT];
    bool failed;
    bool busy;
    bool finishing;    /* inside finish(): errors are the capture's end */
} Columns;

#define NO_TIME INT64_MIN

static int resize(PyObject *array, size_t bytes)
{
    return PyByteArray_Resize(array, (Py_ssize_t)bytes);
}

/* Room for one more row: every array grows by half again when full. */
static int columns_reserve(Columns *self)
{
    size_t i, cap;
    if (self->rows < self->cap) return 0;
    cap = self->cap < 1024 ? 1024 : self->cap + self->cap / 2;
    for (i = 0; i < self->set->count; i++) {
        if (resize(self->data[i], cap * osdk_col_size[self->set->columns[i].type]) < 0 ||
            resize(self->valid[i], cap) < 0)
            return -1;
        self->data_at[i] = PyByteArray_AS_STRING(self->data[i]);
        self->valid_at[i] = (uint8_t *)PyByteArray_AS_STRING(self->valid[i]);
    }
    if (resize(self->offsets, cap * sizeof(uint64_t)) < 0 || resize(self->times, cap * sizeof(int64_t)) < 0) return -1;
    self->cap = cap;
    return 0;
}

static void columns_frame(Columns *self, const osdk_event_t *ev)
{
    osdk_error_t err;
    osdk_frame_t *f = &self->frame;
    const osdk_frame_frame_data_t *fd;
    uint64_t offset = ev->offset;
    int64_t now = self->now;
    osdk_error_clear(&err);
    if (osdk_frame_decode(ev->raw, ev->length, self->profile, f, &err) != OSDK_OK) {
        self->counts[C_ERRORS]++;
        return;
    }
    self->counts[C_FRAMES]++;
    if (f->is_ack || !f->data_present) {
        self->counts[C_OTHER]++;
        return;
    }
    if (f->data.tag != OSDK_FRAME_DATA_FRAME_DATA) { /* encrypted: its command cannot be read */
        self->counts[C_ENCRYPTED]++;
        return;
    }
    fd = &f->data.u.frame_data;
    if (!fd->value_present || fd->value.body.tag != OSDK_PAYLOAD_BODY_BROADCAST) {
        self->counts[C_OTHER]++;
        return;
    }
    if (columns_reserve(self) < 0) {
        self->failed = true;
        return;
    }
    if (!osdk_broadcast_row(&fd->value.body.u.broadcast, self->data_at, self->valid_at, self->rows)) {
        self->counts[C_UNDECODABLE]++;
        return;
    }
    memcpy(PyByteArray_AS_STRING(self->offsets) + self->rows * sizeof(uint64_t), &offset, sizeof offset);
    memcpy(PyByteArray_AS_STRING(self->times) + self->rows * sizeof(int64_t), &now, sizeof now);
    self->rows++;
    self->counts[C_BROADCASTS]++;
}

static void columns_event(void *user, const osdk_event_t *ev)
{
    Columns *self = user;
    if (self->failed) return;
    switch (ev->kind) {
    case OSDK_EVENT_FRAME:
        columns_frame(self, ev);
        break;
    case OSDK_EVENT_GARBAGE:
        self->counts[C_GARBAGE_BYTES] += ev->length;
        break;
    case OSDK_EVENT_ERROR:
    default:
        self->counts[self->finishing ? C_CAPTURE_END : C_ERRORS]++;
        break;
    }
}

static PyObject *columns_run(Columns *self, const uint8_t *data, size_t len, bool finish)
{
    if (self->set == NULL) {
        PyErr_SetString(PyExc_RuntimeError, "Columns.__init__ was not called");
        return NULL;
    }
    if (self->busy) {
        PyErr_SetString(PyExc_RuntimeError, "these Columns are already being filled (another thread)");
        return NULL;
    }
    self->busy = true;
    self->finishing = finish;
    if (finish) osdk_deframer_finish(&self->deframer, columns_event, self);
    else osdk_deframer_feed(&self->deframer, data, len, columns_event, self);
    self->busy = self->finishing = false;
    if (self->failed) return NULL;
    return PyLong_FromSize_t(self->rows);
}

static PyObject *Columns_feed(Columns *self, PyObject *args, PyObject *kwargs)
{
    static char *kwlist[] = {"data", "time_ns", NULL};
    Py_buffer buf;
    PyObject *time = Py_None, *out;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "y*|O:feed", kwlist, &buf, &time)) return NULL;
    if (time == Py_None) {
        self->now = NO_TIME;
    } else {
        long long ns = PyLong_AsLongLong(time);
        if ((ns == -1 && PyErr_Occurred()) || ns == NO_TIME) {
            if (!PyErr_Occurred()) PyErr_SetString(PyExc_OverflowError, "time_ns out of range");
            PyBuffer_Release(&buf);
            return NULL;
        }
        self->now = (int64_t)ns;
    }
    out = columns_run(self, buf.buf, (size_t)buf.len, false);
    PyBuffer_Release(&buf);
    return out;
}

static PyObject *Columns_finish(Columns *self, PyObject *Py_UNUSED(ignored))
{
    return columns_run(self, NULL, 0, true);
}

static PyObject *column_description(const osdk_column_set_t *set, size_t i)
{
    const osdk_column_t *c = &set->columns[i];
    static const char *const codes[OSDK_COL_TYPE_COUNT] = {
        "bool", "u8", "u16", "u32", "u64", "i8", "i16", "i32", "i64", "f32", "f64",
    };
    return Py_BuildValue("(sssz)", c->name, set->items[c->item], codes[c->type], c->enum_name);
}

/* The schema: a tuple of (name, item, element type, enum or None), one per column. */
static PyObject *Columns_schema(Columns *self, PyObject *Py_UNUSED(ignored))
{
    PyObject *out;
    size_t i;
    if (self->set == NULL) {
        PyErr_SetString(PyExc_RuntimeError, "Columns.__init__ was not called");
        return NULL;
    }
    out = PyTuple_New((Py_ssize_t)self->set->count);
    if (out == NULL) return NULL;
    for (i = 0; i < self->set->count; i++) {
        PyObject *d = column_description(self->set, i);
        if (d == NULL) {
            Py_DECREF(out);
            return NULL;
        }
        PyTuple_SET_ITEM(out, (Py_ssize_t)i, d);
    }
    return out;
}

/* Empty arrays for the next rows (those taken, if any, belong to Python now) and
 * counts from zero. 0, or -1 with a Python exception set. */
static int columns_fresh(Columns *self)
{
    size_t i;
    for (i = 0; i < self->set->count; i++) {
        if ((self->data[i] = PyByteArray_FromStringAndSize(NULL, 0)) == NULL ||
            (self->valid[i] = PyByteArray_FromStringAndSize(NULL, 0)) == NULL)
            return -1;
    }
    if ((self->offsets = PyByteArray_FromStringAndSize(NULL, 0)) == NULL ||
        (self->times = PyByteArray_FromStringAndSize(NULL, 0)) == NULL)
        return -1;
    self->rows = self->cap = 0;
    memset(self->counts, 0, sizeof self->counts);
    return 0;
}

/* Hands the filled arrays over, cut to the rows made, and starts a new set. */
static PyObject *Columns_take(Columns *self, PyObject *Py_UNUSED(ignored))
{
    PyObject *data = NULL, *valid = NULL, *counts = NULL, *out = NULL;
    size_t i, n;
    if (self->set == NULL || self->busy) {
        PyErr_SetString(PyExc_RuntimeError, self->set == NULL ? "Columns.__init__ was not called"
                                                              : "these Columns are being filled");
        return NULL;
    }
    n = self->set->count;
    data = PyTuple_New((Py_ssize_t)n);
    valid = PyTuple_New((Py_ssize_t)n);
    counts = PyDict_New();
    if (data == NULL || valid == NULL || counts == NULL) goto done;
    for (i = 0; i < n; i++) {
        PyObject *d = self->data[i], *v = self->valid[i];
        if (resize(d, self->rows * osdk_col_size[self->set->columns[i].type]) < 0 || resize(v, self->rows) < 0) goto done;
        PyTuple_SET_ITEM(data, (Py_ssize_t)i, d);
        PyTuple_SET_ITEM(valid, (Py_ssize_t)i, v);
        self->data[i] = self->valid[i] = NULL;
    }
    if (resize(self->offsets, self->rows * sizeof(uint64_t)) < 0 || resize(self->times, self->rows * sizeof(int64_t)) < 0)
        goto done;
    for (i = 0; i < C_COUNT; i++) {
        PyObject *v = PyLong_FromUnsignedLongLong(self->counts[i]);
        if (v == NULL || PyDict_SetItemString(counts, count_names[i], v) < 0) {
            Py_XDECREF(v);
            goto done;
        }
        Py_DECREF(v);
    }
    out = Py_BuildValue("{s:n,s:O,s:O,s:O,s:O,s:O}", "rows", (Py_ssize_t)self->rows, "data", data, "valid", valid,
                        "offset", self->offsets, "time", self->times, "counts", counts);
    if (out == NULL) goto done;
    Py_CLEAR(self->offsets);
    Py_CLEAR(self->times);
    /* a fresh set of empty arrays; the stream (deframer) goes on */
    if (columns_fresh(self) < 0) {
        self->failed = true;
        Py_CLEAR(out);
    }
done:
    Py_XDECREF(data);
    Py_XDECREF(valid);
    Py_XDECREF(counts);
    return out;
}

static void columns_free_arrays(Columns *self)
{
    size_t i;
    if (self->set != NULL) {
        for (i = 0; i < self->set->count; i++) {
            if (self->data) Py_CLEAR(self->data[i]);
            if (self->valid) Py_CLEAR(self->valid[i]);
        }
    }
    PyMem_Free(self->data);
    PyMem_Free(self->valid);
    PyMem_Free(self->data_at);
    PyMem_Free(self->valid_at);
    self->data = self->valid = NULL;
    self->data_at = NULL;
    self->valid_at = NULL;
    Py_CLEAR(self->offsets);
    Py_CLEAR(self->times);
}

static int Columns_init(Columns *self, PyObject *args, PyObject *kwargs)
{
    static char *kwlist[] = {"profile", NULL};
    unsigned char profile;
    const osdk_column_set_t *set;
    size_t n;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "b:Columns", kwlist, &profile)) return -1;
    if (self->busy) {
        PyErr_SetString(PyExc_RuntimeError, "these Columns are being filled");
        return -1;
    }
    set = osdk_broadcast_columns(profile);
    if (set == NULL) {
        PyErr_Format(PyExc_ValueError, "no broadcast layout for profile value %u", (unsigned)profile);
        return -1;
    }
    columns_free_arrays(self);
    n = set->count;
    self->set = set;
    self->data = PyMem_Calloc(n, sizeof(PyObject *));
    self->valid = PyMem_Calloc(n, sizeof(PyObject *));
    self->data_at = PyMem_Calloc(n, sizeof(void *));
    self->valid_at = PyMem_Calloc(n, sizeof(uint8_t *));
    if (self->data == NULL || self->valid == NULL || self->data_at == NULL || self->valid_at == NULL) {
        PyErr_NoMemory();
        return -1;
    }
    if (columns_fresh(self) < 0) return -1;
    self->profile = profile;
    self->now = NO_TIME;
    self->failed = false;
    osdk_deframer_init(&self->deframer, self->window, sizeof self->window);
    return 0;
}

static void Columns_dealloc(Columns *self)
{
    columns_free_arrays(self);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

static PyMethodDef Columns_methods[] = {
    {"feed", (PyCFunction)(void (*)(void))Columns_feed, METH_VARARGS | METH_KEYWORDS,
     "feed(data, time_ns=None) -> rows so far. time_ns: the capture time of these bytes (ns since the Unix "
     "epoch), for the frames they complete; None when the bytes came without one (a row's time is then "
     "INT64_MIN)."},
    {"finish", (PyCFunction)Columns_finish, METH_NOARGS, "finish() -> rows so far, the end of the input seen."},
    {"schema", (PyCFunction)Columns_schema, METH_NOARGS,
     "schema() -> ((name, item, element type, enum or None), ...), one per column, in the order of take()'s."},
    {"take", (PyCFunction)Columns_take, METH_NOARGS,
     "take() -> {'rows', 'data', 'valid', 'offset', 'time', 'counts'}: the rows made so far, as bytearrays; "
     "the next rows start empty."},
    {NULL, NULL, 0, NULL},
};

static PyTypeObject ColumnsType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "osdk_conformance.reference._accel.Columns",
    .tp_basicsize = sizeof(Columns),
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "Columns(profile): the broadcasts of a received stream as typed columns (osdk_columns.h).\n"
              "profile is the u8 value of the wire profile (spec/rules.yaml).",
    .tp_new = PyType_GenericNew,
    .tp_init = (initproc)Columns_init,
    .tp_dealloc = (destructor)Columns_dealloc,
    .tp_methods = Columns_methods,
};

/* ---- single frames and payloads (the testee protocol's decode_frame / decode_payload) ------------ */

static osdk_frame_t one_frame;
static osdk_payload_t one_payload;

static PyObject *raise_decode(osdk_status_t status, PyObject *detail)
{
    if (detail != NULL) {
        PyObject *exc = Py_BuildValue("(sN)", osdk_status_name(status), detail);
        if (exc != NULL) {
            PyErr_SetObject(DecodeError, exc);
            Py_DECREF(exc);
        }
    }
    return NULL;
}

static PyObject *accel_decode_frame(PyObject *module, PyObject *args)
{
    Py_buffer buf;
    unsigned char profile;
    char detail[256];
    osdk_status_t st;
    osdk_error_t err;
    PyObject *out;
    (void)module;
    if (!PyArg_ParseTuple(args, "y*b:decode_frame", &buf, &profile)) return NULL;
    st = osdk_frame_problem(buf.buf, (size_t)buf.len, detail, sizeof detail);
    if (st != OSDK_OK) {
        PyBuffer_Release(&buf);
        return raise_decode(st, PyUnicode_FromString(detail));
    }
    osdk_error_clear(&err);
    if (osdk_frame_decode(buf.buf, (size_t)buf.len, profile, &one_frame, &err) != OSDK_OK) {
        PyBuffer_Release(&buf);
        return raise_decode(err.status, detail_of(&err));
    }
    out = osdk_frame_to_py(&one_frame); /* before the buffer goes: byte fields point into it */
    PyBuffer_Release(&buf);
    return out;
}

static PyObject *accel_decode_payload(PyObject *module, PyObject *args)
{
    Py_buffer buf;
    unsigned char cmd_set, cmd_id, profile;
    int is_ack;
    osdk_error_t err;
    PyObject *out;
    (void)module;
    if (!PyArg_ParseTuple(args, "y*bbpb:decode_payload", &buf, &cmd_set, &cmd_id, &is_ack, &profile)) return NULL;
    osdk_error_clear(&err);
    if (osdk_payload_decode(buf.buf, (size_t)buf.len, cmd_set, cmd_id, is_ack != 0, profile, &one_payload, &err) !=
        OSDK_OK) {
        PyBuffer_Release(&buf);
        return raise_decode(err.status, detail_of(&err));
    }
    out = osdk_payload_to_py(&one_payload);
    PyBuffer_Release(&buf);
    return out;
}

static PyMethodDef module_methods[] = {
    {"decode_frame", accel_decode_frame, METH_VARARGS,
     "decode_frame(data, profile) -> the model of osdk_frame; DecodeError(class, detail) when the receiver's "
     "checks or the decoder reject it."},
    {"decode_payload", accel_decode_payload, METH_VARARGS,
     "decode_payload(data, cmd_set, cmd_id, is_ack, profile) -> the model of osdk_payload; DecodeError(class, "
     "detail) on failure."},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef accel_module = {
    PyModuleDef_HEAD_INIT, "osdk_conformance.reference._accel",
    "The generated C decoder as a native extension (see osdk_conformance/reference/accel.py).", -1, module_methods,
    NULL, NULL, NULL, NULL,
};

PyMODINIT_FUNC PyInit__accel(void)
{
    PyObject *m;
    size_t i;
    if (osdk_model_py_init() < 0) return NULL;
    for (i = 0; i < TEXT_COUNT; i++) {
        if (text[i] == NULL && (text[i] = PyUnicode_InternFromString(text_values[i])) == NULL) return NULL;
    }
    if (PyType_Ready(&DecoderType) < 0 || PyType_Ready(&ColumnsType) < 0) return NULL;
    m = PyModule_Create(&accel_module);
    if (m == NULL) return NULL;
    DecodeError = PyErr_NewExceptionWithDoc("osdk_conformance.reference._accel.DecodeError",
                                            "A rejected frame or payload: args are (error class, detail).",
                                            PyExc_ValueError, NULL);
    if (DecodeError == NULL || PyModule_AddObjectRef(m, "DecodeError", DecodeError) < 0 ||
        PyModule_AddObjectRef(m, "Decoder", (PyObject *)&DecoderType) < 0 ||
        PyModule_AddObjectRef(m, "Columns", (PyObject *)&ColumnsType) < 0) {
        Py_DECREF(m);
        return NULL;
    }
    return m;
}
