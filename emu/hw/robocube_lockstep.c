/*
 * Lockstep device: pauses the whole machine at every step boundary of
 * virtual time (k * step-ns, k = 1, 2, ...), so that a host-side world
 * simulation can read the actuators, integrate, write the sensors and let
 * the machine go on with QMP `cont` (emu/world/, emu/README.md "Lockstep").
 *
 * QOM path /machine/lockstep; `step-ns` is settable with qom-set or at start
 * with -global robocube-lockstep.step-ns=N (0 = off, the default).
 *
 * Batched access. QMP handles one command per main-loop turn (about 0.5 ms
 * on the shared 2-core machine), so a step that read and wrote a dozen
 * properties one by one would cost more than the emulation itself. The host
 * names, once, the integer properties it reads every step (`sample-props`)
 * and those it writes (`input-props`), as "PATH:PROPERTY" separated by
 * spaces; then one qom-get of `sample` returns all the values read and one
 * qom-set of `inputs` writes all the inputs (each through its own property,
 * with its own range check; the first refused value stops the write with
 * that property's error).
 *
 * Why two timers. The boundary timer (main-loop timer list) fires at the
 * boundary and asks the main loop to stop the VM; it cannot stop the VM
 * itself (vm_stop from a timer callback waits for the timer list it is
 * running in). Between that request and the stop, nothing may let the vCPU
 * execute further instructions, or the stop would land a load-dependent
 * number of instructions late. Under -icount the vCPU's instruction budget
 * ends at the earliest deadline of all QEMU_CLOCK_VIRTUAL timer lists, so a
 * second "guard" timer, on a private timer list that nobody ever runs,
 * stays armed at the boundary until the VM has stopped: the budget stays 0
 * and the vCPU cannot move. On resume (a VM state change handler, which runs
 * before the vCPUs resume) the guard moves to the next boundary.
 * Without -icount the stop is still made, but not at an exact instruction.
 *
 * Frame channel (optional, -global robocube-lockstep.chardev=ID): instead
 * of a QMP round trip per property and per `cont`, each stop sends one
 * line "S STEPS BOUNDARY_NS V1 V2 ...\n" (the sample-props values) on the
 * chardev, and the host answers "I V1 V2 ...\n" (the input-props values):
 * the device writes the inputs and resumes the VM itself. A refused line is
 * answered "E message\n" and the VM stays paused. This is the fast path of
 * emu/world/cosim.py; QMP still works alongside.
 */
#include "qemu/osdep.h"
#include "qemu/module.h"
#include "qemu/timer.h"
#include "qapi/error.h"
#include "qapi/visitor.h"
#include "qapi/qapi-builtin-visit.h"
#include "hw/qdev-core.h"
#include "hw/qdev-properties.h"
#include "hw/qdev-properties-system.h"
#include "chardev/char-fe.h"
#include "sysemu/runstate.h"
#include "robocube_board.h"

OBJECT_DECLARE_SIMPLE_TYPE(RoboCubeLockstep, ROBOCUBE_LOCKSTEP)

struct RoboCubeLockstep {
    DeviceState parent_obj;
    uint64_t step_ns;          /* 0 = off */
    uint64_t origin_ns;        /* boundaries at origin + k * step */
    uint64_t next_boundary;    /* virtual ns of the next stop */
    uint64_t boundary;         /* virtual ns of the last stop (0 before any) */
    uint64_t steps;            /* boundaries reached */
    bool stop_pending;         /* requested, VM not yet resumed */
    QEMUTimer boundary_timer;
    QEMUTimerListGroup guard_tlg;
    QEMUTimer guard_timer;
    /* Batched access: the parsed "PATH:PROPERTY" lists. */
    char *sample_spec, *input_spec;
    GPtrArray *sample_obj, *sample_prop;
    GPtrArray *input_obj, *input_prop;
    /* Frame channel. */
    CharBackend chr;
    char line[4096];
    size_t line_len;
};

static void lockstep_guard_cb(void *opaque)
{
    /* Never called: the guard's timer list is not run by anyone. */
}

/* The guard's list never wakes anyone: the boundary timer, armed at the
 * same deadline on the main loop's list, does (and a NULL callback would
 * make QEMU's clock notification recurse through qemu_notify_event). */
static void lockstep_guard_notify(void *opaque, QEMUClockType type)
{
}

static void lockstep_arm(RoboCubeLockstep *ls)
{
    if (ls->step_ns == 0) {
        timer_del(&ls->boundary_timer);
        timer_del(&ls->guard_timer);
        return;
    }
    timer_mod(&ls->boundary_timer, (int64_t)ls->next_boundary);
    if (!ls->stop_pending) {
        timer_mod(&ls->guard_timer, (int64_t)ls->next_boundary);
    }
}

static void lockstep_boundary_cb(void *opaque)
{
    RoboCubeLockstep *ls = opaque;

    ls->boundary = ls->next_boundary;
    ls->steps++;
    ls->next_boundary += ls->step_ns;
    ls->stop_pending = true;
    /* The guard stays at the boundary just reached until the VM resumes. */
    timer_mod(&ls->boundary_timer, (int64_t)ls->next_boundary);
    qemu_system_vmstop_request_prepare();
    qemu_system_vmstop_request(RUN_STATE_PAUSED);
}

static bool lockstep_read_samples(RoboCubeLockstep *ls, GString *out, Error **errp);

static void lockstep_vm_state(void *opaque, bool running, RunState state)
{
    RoboCubeLockstep *ls = opaque;

    if (running && ls->stop_pending) {
        ls->stop_pending = false;
        lockstep_arm(ls);
    } else if (!running && ls->stop_pending && qemu_chr_fe_backend_connected(&ls->chr)) {
        /* Stopped at a boundary: send the frame (the vCPUs are paused now). */
        g_autoptr(GString) frame = g_string_new(NULL);
        Error *err = NULL;
        g_string_append_printf(frame, "S %" PRIu64 " %" PRIu64, ls->steps, ls->boundary);
        if (!lockstep_read_samples(ls, frame, &err)) {
            g_string_printf(frame, "E %s", error_get_pretty(err));
            error_free(err);
        }
        g_string_append_c(frame, '\n');
        qemu_chr_fe_write_all(&ls->chr, (const uint8_t *)frame->str, frame->len);
    }
}

static void lockstep_get_u64(Object *obj, Visitor *v, const char *name,
                             void *opaque, Error **errp)
{
    uint64_t *field = opaque;
    visit_type_uint64(v, name, field, errp);
}

static void lockstep_get_step(Object *obj, Visitor *v, const char *name,
                              void *opaque, Error **errp)
{
    visit_type_uint64(v, name, &ROBOCUBE_LOCKSTEP(obj)->step_ns, errp);
}

static void lockstep_get_now(Object *obj, Visitor *v, const char *name,
                             void *opaque, Error **errp)
{
    uint64_t now = (uint64_t)qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL);
    visit_type_uint64(v, name, &now, errp);
}

/* The next boundary origin + k * step strictly after now (k may be < 0
 * relative to a future origin). */
static void lockstep_rebase(RoboCubeLockstep *ls)
{
    uint64_t now = (uint64_t)qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL);
    uint64_t phase;

    if (ls->step_ns) {
        phase = ls->origin_ns % ls->step_ns;
        ls->next_boundary = now < phase ? phase
                          : ((now - phase) / ls->step_ns + 1) * ls->step_ns + phase;
    }
    lockstep_arm(ls);
}

static void lockstep_set_step(Object *obj, Visitor *v, const char *name,
                              void *opaque, Error **errp)
{
    RoboCubeLockstep *ls = ROBOCUBE_LOCKSTEP(obj);
    uint64_t value;

    if (!visit_type_uint64(v, name, &value, errp)) {
        return;
    }
    if (value != 0 && value < 1000) {
        error_setg(errp, "step-ns: %" PRIu64 " is below 1000 ns (0 turns lockstep off)",
                   value);
        return;
    }
    ls->step_ns = value;
    lockstep_rebase(ls);
}

static void lockstep_get_origin(Object *obj, Visitor *v, const char *name,
                                void *opaque, Error **errp)
{
    visit_type_uint64(v, name, &ROBOCUBE_LOCKSTEP(obj)->origin_ns, errp);
}

static void lockstep_set_origin(Object *obj, Visitor *v, const char *name,
                                void *opaque, Error **errp)
{
    RoboCubeLockstep *ls = ROBOCUBE_LOCKSTEP(obj);
    uint64_t value;

    if (!visit_type_uint64(v, name, &value, errp)) {
        return;
    }
    ls->origin_ns = value;
    lockstep_rebase(ls);
}

/* Parses "PATH:PROP PATH:PROP ..." into objects and property names; every
 * object and property must exist. On error, nothing changes. */
static bool lockstep_parse_props(const char *spec, GPtrArray **objs, GPtrArray **props,
                                 const char *what, Error **errp)
{
    g_auto(GStrv) words = g_strsplit_set(spec, " \t\n", -1);
    GPtrArray *o = g_ptr_array_new();
    GPtrArray *p = g_ptr_array_new_with_free_func(g_free);

    for (char **w = words; *w; w++) {
        char *colon;
        Object *obj;
        if (!**w) {
            continue;
        }
        colon = strrchr(*w, ':');
        if (!colon || colon == *w || !colon[1]) {
            error_setg(errp, "%s: '%s' is not PATH:PROPERTY", what, *w);
            goto fail;
        }
        *colon = 0;
        obj = object_resolve_path(*w, NULL);
        if (!obj) {
            error_setg(errp, "%s: no object at '%s'", what, *w);
            goto fail;
        }
        if (!object_property_find(obj, colon + 1)) {
            error_setg(errp, "%s: '%s' has no property '%s'", what, *w, colon + 1);
            goto fail;
        }
        g_ptr_array_add(o, obj);
        g_ptr_array_add(p, g_strdup(colon + 1));
    }
    if (*objs) {
        g_ptr_array_free(*objs, true);
        g_ptr_array_free(*props, true);
    }
    *objs = o;
    *props = p;
    return true;
fail:
    g_ptr_array_free(o, true);
    g_ptr_array_free(p, true);
    return false;
}

static char *lockstep_get_sample_spec(Object *obj, Error **errp)
{
    RoboCubeLockstep *ls = ROBOCUBE_LOCKSTEP(obj);
    return g_strdup(ls->sample_spec ? ls->sample_spec : "");
}

static void lockstep_set_sample_spec(Object *obj, const char *value, Error **errp)
{
    RoboCubeLockstep *ls = ROBOCUBE_LOCKSTEP(obj);
    if (lockstep_parse_props(value, &ls->sample_obj, &ls->sample_prop, "sample-props", errp)) {
        g_free(ls->sample_spec);
        ls->sample_spec = g_strdup(value);
    }
}

static char *lockstep_get_input_spec(Object *obj, Error **errp)
{
    RoboCubeLockstep *ls = ROBOCUBE_LOCKSTEP(obj);
    return g_strdup(ls->input_spec ? ls->input_spec : "");
}

static void lockstep_set_input_spec(Object *obj, const char *value, Error **errp)
{
    RoboCubeLockstep *ls = ROBOCUBE_LOCKSTEP(obj);
    if (lockstep_parse_props(value, &ls->input_obj, &ls->input_prop, "input-props", errp)) {
        g_free(ls->input_spec);
        ls->input_spec = g_strdup(value);
    }
}

/* Reads every sample property; appends " V" per value to out if given,
 * and to *list if given. */
static bool lockstep_sample_values(RoboCubeLockstep *ls, GString *out, intList ***tail,
                                   Error **errp)
{
    unsigned n = ls->sample_obj ? ls->sample_obj->len : 0;

    for (unsigned i = 0; i < n; i++) {
        Error *err = NULL;
        int64_t value = object_property_get_int(g_ptr_array_index(ls->sample_obj, i),
                                                g_ptr_array_index(ls->sample_prop, i), &err);
        if (err) {
            error_propagate(errp, err);
            return false;
        }
        if (out) {
            g_string_append_printf(out, " %" PRId64, value);
        }
        if (tail) {
            QAPI_LIST_APPEND(*tail, value);
        }
    }
    return true;
}

static bool lockstep_read_samples(RoboCubeLockstep *ls, GString *out, Error **errp)
{
    return lockstep_sample_values(ls, out, NULL, errp);
}

static void lockstep_get_sample(Object *obj, Visitor *v, const char *name,
                                void *opaque, Error **errp)
{
    RoboCubeLockstep *ls = ROBOCUBE_LOCKSTEP(obj);
    intList *head = NULL, **tail = &head;

    if (lockstep_sample_values(ls, NULL, &tail, errp)) {
        visit_type_intList(v, name, &head, errp);
    }
    qapi_free_intList(head);
}

/* Writes n values to the input properties; false (and errp) on the first
 * refused value or a count mismatch. */
static bool lockstep_write_inputs(RoboCubeLockstep *ls, const int64_t *values, unsigned count,
                                  Error **errp)
{
    unsigned n = ls->input_obj ? ls->input_obj->len : 0;

    if (count != n) {
        error_setg(errp, "inputs: %u values for %u input-props", count, n);
        return false;
    }
    for (unsigned i = 0; i < n; i++) {
        if (!object_property_set_int(g_ptr_array_index(ls->input_obj, i),
                                     g_ptr_array_index(ls->input_prop, i), values[i], errp)) {
            return false;
        }
    }
    return true;
}

static void lockstep_set_inputs(Object *obj, Visitor *v, const char *name,
                                void *opaque, Error **errp)
{
    RoboCubeLockstep *ls = ROBOCUBE_LOCKSTEP(obj);
    intList *list = NULL;
    g_autoptr(GArray) values = g_array_new(false, false, sizeof(int64_t));

    if (!visit_type_intList(v, name, &list, errp)) {
        return;
    }
    for (intList *e = list; e; e = e->next) {
        g_array_append_val(values, e->value);
    }
    qapi_free_intList(list);
    lockstep_write_inputs(ls, (const int64_t *)values->data, values->len, errp);
}

/* ---- frame channel ---- */
static void lockstep_reply_error(RoboCubeLockstep *ls, Error *err)
{
    g_autofree char *msg = g_strdup_printf("E %s\n", error_get_pretty(err));
    qemu_chr_fe_write_all(&ls->chr, (const uint8_t *)msg, strlen(msg));
    error_free(err);
}

/* One complete line from the host: "I V1 V2 ...". */
static void lockstep_handle_line(RoboCubeLockstep *ls, char *line)
{
    g_autoptr(GArray) values = g_array_new(false, false, sizeof(int64_t));
    Error *err = NULL;
    char *p = line + 1, *end;

    if (line[0] != 'I') {
        error_setg(&err, "lockstep frame: expected 'I values...', got '%.40s'", line);
        lockstep_reply_error(ls, err);
        return;
    }
    for (;;) {
        int64_t v;
        while (*p == ' ') {
            p++;
        }
        if (!*p) {
            break;
        }
        errno = 0;
        v = strtoll(p, &end, 10);
        if (end == p || errno || (*end && *end != ' ')) {
            error_setg(&err, "lockstep frame: '%.20s' is not an integer", p);
            lockstep_reply_error(ls, err);
            return;
        }
        g_array_append_val(values, v);
        p = end;
    }
    if (!lockstep_write_inputs(ls, (const int64_t *)values->data, values->len, &err)) {
        lockstep_reply_error(ls, err);
        return;
    }
    if (runstate_check(RUN_STATE_PAUSED)) {
        vm_start();
    }
}

static int lockstep_can_read(void *opaque)
{
    RoboCubeLockstep *ls = opaque;
    return (int)(sizeof(ls->line) - ls->line_len);
}

static void lockstep_read(void *opaque, const uint8_t *buf, int size)
{
    RoboCubeLockstep *ls = opaque;

    for (int i = 0; i < size; i++) {
        if (buf[i] == '\n') {
            ls->line[ls->line_len] = 0;
            lockstep_handle_line(ls, ls->line);
            ls->line_len = 0;
        } else if (ls->line_len < sizeof(ls->line) - 1) {
            ls->line[ls->line_len++] = (char)buf[i];
        } else {
            Error *err = NULL;
            error_setg(&err, "lockstep frame: line longer than %zu bytes", sizeof(ls->line) - 1);
            lockstep_reply_error(ls, err);
            ls->line_len = 0;
        }
    }
}

static void lockstep_realize(DeviceState *dev, Error **errp)
{
    RoboCubeLockstep *ls = ROBOCUBE_LOCKSTEP(dev);
    if (qemu_chr_fe_backend_connected(&ls->chr)) {
        qemu_chr_fe_set_handlers(&ls->chr, lockstep_can_read, lockstep_read, NULL, NULL, ls,
                                 NULL, true);
    }
}

static Property lockstep_properties[] = {
    DEFINE_PROP_CHR("chardev", RoboCubeLockstep, chr),
    DEFINE_PROP_END_OF_LIST(),
};

static void lockstep_instance_init(Object *obj)
{
    RoboCubeLockstep *ls = ROBOCUBE_LOCKSTEP(obj);

    timer_init_ns(&ls->boundary_timer, QEMU_CLOCK_VIRTUAL, lockstep_boundary_cb, ls);
    timerlistgroup_init(&ls->guard_tlg, lockstep_guard_notify, ls);
    timer_init_full(&ls->guard_timer, &ls->guard_tlg, QEMU_CLOCK_VIRTUAL, SCALE_NS, 0,
                    lockstep_guard_cb, ls);
    qemu_add_vm_change_state_handler(lockstep_vm_state, ls);
}

static void lockstep_class_init(ObjectClass *oc, void *data)
{
    DeviceClass *dc = DEVICE_CLASS(oc);

    dc->desc = "RoboCube lockstep: pauses the VM at every step-ns of virtual time";
    dc->user_creatable = false;
    dc->realize = lockstep_realize;
    device_class_set_props(dc, lockstep_properties);
    object_class_property_add(oc, "step-ns", "uint64", lockstep_get_step, lockstep_set_step, NULL, NULL);
    object_class_property_set_description(oc, "step-ns",
        "virtual ns between stops (0 = off); boundaries at k * step-ns");
    object_class_property_add(oc, "origin-ns", "uint64", lockstep_get_origin,
                              lockstep_set_origin, NULL, NULL);
    object_class_property_set_description(oc, "origin-ns",
        "boundaries at origin-ns + k * step-ns (default 0); the next one after now");
    object_class_property_add_str(oc, "sample-props", lockstep_get_sample_spec,
                                  lockstep_set_sample_spec);
    object_class_property_add_str(oc, "input-props", lockstep_get_input_spec,
                                  lockstep_set_input_spec);
    object_class_property_add(oc, "sample", "intList", lockstep_get_sample, NULL, NULL, NULL);
    object_class_property_add(oc, "inputs", "intList", NULL, lockstep_set_inputs, NULL, NULL);
}

static void lockstep_instance_props(RoboCubeLockstep *ls)
{
    Object *o = OBJECT(ls);
    /* Counters (per instance: they point into ls). */
    object_property_add(o, "steps", "uint64", lockstep_get_u64, NULL, NULL, &ls->steps);
    object_property_add(o, "boundary-ns", "uint64", lockstep_get_u64, NULL, NULL,
                        &ls->boundary);
    object_property_add(o, "next-boundary-ns", "uint64", lockstep_get_u64, NULL, NULL,
                        &ls->next_boundary);
    object_property_add(o, "virtual-time-ns", "uint64", lockstep_get_now, NULL, NULL, NULL);
}

void robocube_lockstep_create(void)
{
    DeviceState *dev = qdev_new(TYPE_ROBOCUBE_LOCKSTEP);

    object_property_add_child(qdev_get_machine(), "lockstep", OBJECT(dev));
    lockstep_instance_props(ROBOCUBE_LOCKSTEP(dev));
    qdev_realize_and_unref(dev, NULL, &error_fatal);
}

static const TypeInfo lockstep_info = {
    .name = TYPE_ROBOCUBE_LOCKSTEP,
    .parent = TYPE_DEVICE,
    .instance_size = sizeof(RoboCubeLockstep),
    .instance_init = lockstep_instance_init,
    .class_init = lockstep_class_init,
};

static void lockstep_register_types(void)
{
    type_register_static(&lockstep_info);
}

type_init(lockstep_register_types)
