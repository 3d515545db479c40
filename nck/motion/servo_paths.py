"""Fast paths of :class:`nck.motion.servo.ServoBank` for blocks without injected faults.

* :func:`process_small`: blocks of a few IPO cycles, cycle by cycle in Python
  floats (the per-cycle recurrence; cheaper than numpy on 3-element arrays);
* :func:`process_fast`: longer blocks in one numpy pass, the monitors proven
  silent by bounds.

Both return None, with nothing changed, when a monitor might respond; the
bank then runs its full model, which locates the responding cycle. The
functions read the tables and update the state of a
:class:`nck.motion.servo_model.ServoModel` (the bank's).
"""

from __future__ import annotations

import numpy as np

from nck.motion.servo_model import AMBIENT_C, MOVING_MM_S, ServoModel


def process_small(model: ServoModel, x: np.ndarray) -> np.ndarray | None:
    """A few cycles without faults, cycle by cycle in Python floats (cheaper than numpy here).

    The same recurrence and monitors as :meth:`ServoBank._process_one`; when a
    monitor would respond, None is returned with nothing changed and the
    caller runs the full model, which locates the responding cycle.
    """
    T = model.T
    inv_t = model.inv_t
    m, n = x.shape
    rows = x.tolist()
    lim = model.small_limits
    x_set = model.x_set.tolist()
    v_set = model.v_set.tolist()
    e = model.e.tolist()
    e_model = model.e_model.tolist()
    stop_cycles = model.stop_cycles.tolist()
    fine_since = model.fine_since_stop.tolist()
    clamped = model.clamped.tolist()
    temperature = model.temperature.tolist()
    actual_rows = []
    a = v_act = v_cmd = torque = v_set
    for row in rows:
        out = [0.0] * n
        v_row = [0.0] * n
        a_row = [0.0] * n
        v_act_row = [0.0] * n
        v_cmd_row = [0.0] * n
        torque_row = [0.0] * n
        for i in range(n):
            (alpha, b, kv, ffw_net, contour, ctrlout, velo, fine_lim, pos_time, still_delay, still, clamp,
             mass_dv, friction, gravity, inv_rated, temp_rise, decay) = lim[i]
            xi = row[i]
            v = (xi - x_set[i]) * inv_t
            em = alpha * e_model[i] + b * v
            dev = (e[i] - e_model[i]) * alpha
            ei = em + dev
            act = xi - ei
            va = (act - (x_set[i] - e[i])) * inv_t
            vc = kv * ei + ffw_net * v
            moving = abs(v) > MOVING_MM_S
            abs_e = abs(ei)
            fine = abs_e <= fine_lim and not moving
            since_s = 0.0 if moving else (stop_cycles[i] + 1) * T
            reached = not moving and (fine_since[i] or fine)
            if (abs(dev) > contour or abs(vc) > ctrlout or abs(va) > velo
                    or (not moving and not reached and since_s > pos_time)
                    or (not moving and reached and since_s >= still_delay
                        and abs_e > (clamp if clamped[i] else still))):
                return None  # a monitor responds: the full model decides where
            stop_cycles[i] = 0 if moving else stop_cycles[i] + 1
            fine_since[i] = False if moving else (fine_since[i] or fine)
            acc = (v - v_set[i]) * inv_t
            tq = mass_dv * acc * T + friction * (1.0 if va > 0 else -1.0 if va < 0 else 0.0) + gravity
            target = AMBIENT_C + temp_rise * (tq * inv_rated) ** 2
            temperature[i] = target + (temperature[i] - target) * decay
            x_set[i] = xi
            v_set_i = v
            e[i] = ei
            e_model[i] = em
            out[i] = act
            v_row[i] = v_set_i
            a_row[i] = acc
            v_act_row[i] = va
            v_cmd_row[i] = vc
            torque_row[i] = tq
        v_set = v_row
        a, v_act, v_cmd, torque = a_row, v_act_row, v_cmd_row, torque_row
        actual_rows.append(out)
    model.x_set = np.array(x_set)
    model.v_set = np.array(v_set)
    model.a_set = np.array(a)
    model.e = np.array(e)
    model.e_model = np.array(e_model)
    model.v_act = np.array(v_act)
    model.v_cmd = np.array(v_cmd)
    model.torque = np.array(torque)
    model.temperature = np.array(temperature)
    model.stop_cycles = np.array(stop_cycles, dtype=np.int64)
    model.fine_since_stop = np.array(fine_since, dtype=bool)
    return np.array(actual_rows)

def process_fast(model: ServoModel, x: np.ndarray) -> np.ndarray | None:
    """The common block (no faults, monitors on): the model of :meth:`ServoBank.process`, cheaper.

    The monitors are checked through bounds that prove no monitor can
    respond anywhere in the block: every value below its limit, and every
    stopped axis inside its fine window and its standstill tolerances (so
    neither positioning nor zero-speed monitoring can respond). When a
    bound fails, None is returned with nothing changed and the caller runs
    the full model, which locates the responding cycle.
    """
    m = x.shape[0]
    inv_t = model.inv_t
    lim = model.limits
    v = np.empty_like(x)
    np.subtract(x[0], model.x_set, out=v[0])
    np.subtract(x[1:], x[:-1], out=v[1:])
    v *= inv_t
    powers = model.powers[:m]
    # e_model[k] = alpha^k (e_model0 + sum_j<=k b v[j] alpha^-j)
    acc = np.cumsum(v * model.b_inv_powers[:m], axis=0)
    acc += model.e_model
    e_model = acc
    e_model *= powers
    dev0 = model.e - model.e_model
    if dev0.any():
        if (np.abs(dev0) * model.alpha > lim["contour"]).any():
            return None  # the contour deviation only decays: its first cycle is its largest
        e = e_model + dev0 * powers
    else:
        e = e_model
    v_cmd = model.kv * e
    v_cmd += model.ffw_net * v
    if (np.abs(v_cmd) > model.ctrlout_mm_s).any():
        return None
    actual = x - e
    v_act = np.empty_like(x)
    np.subtract(actual[0], model.x_set - model.e, out=v_act[0])
    np.subtract(actual[1:], actual[:-1], out=v_act[1:])
    v_act *= inv_t
    if (np.abs(v_act) > lim["velo"]).any():
        return None
    stopped = np.abs(v) <= MOVING_MM_S
    if stopped.any():
        if (stopped & (np.abs(e) > model.small_e)).any():
            return None  # a stopped axis outside its windows: the standstill monitors decide
        # Standstill book-keeping; every stopped cycle is inside the fine window here.
        last = m - 1 - np.argmax(~stopped[::-1], axis=0)
        any_move = ~stopped[last, model.cols]
        fine_after = last < m - 1
        model.stop_cycles = np.where(any_move, m - 1 - last, model.stop_cycles + m)
        model.fine_since_stop = np.where(any_move, fine_after, model.fine_since_stop | fine_after)
    else:
        model.stop_cycles = model.zero_cycles
        model.fine_since_stop = model.no_fine
    # Drive values: torque from acceleration, friction and weight; motor temperature.
    dv = np.empty_like(v)
    np.subtract(v[0], model.v_set, out=dv[0])
    np.subtract(v[1:], v[:-1], out=dv[1:])
    torque = model.torque_per_dv * dv
    torque += model.torque_friction * np.sign(v_act)
    torque += model.torque_gravity
    load = model.ones[:m] @ np.square(torque * model.inv_rated_torque)
    target = AMBIENT_C + model.temp_rise_per_m[m] * load if m < len(model.temp_rise_per_m) else (
        AMBIENT_C + model.mech["temp_rise"] * load / m)
    model.temperature = target + (model.temperature - target) * model.decay_pow[m]
    model.torque = torque[-1]
    model.a_set = dv[-1] * inv_t
    model.x_set = x[-1].copy()
    model.v_set = v[-1]
    model.e = e[-1].copy()  # (e may be e_model itself: two separate arrays)
    model.e_model = e_model[-1]
    model.v_act = v_act[-1]
    model.v_cmd = v_cmd[-1]
    return actual
