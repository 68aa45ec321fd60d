#!/usr/bin/env python3
"""Writes what MuJoCo's compiler makes of each MJCF fixture in tests/fixtures/mujoco/: for NAME.xml,
NAME.poses.json beside it, holding the poses of every body and site (world position, rotation
matrix by rows, as MuJoCo's xpos and xmat give them) at a few configurations, and each joint's
qpos entries there.

cargo test reads the JSON files and holds the reader to them (tests/mjcf_mujoco.rs); it never
runs this script. Run it after changing a fixture:

    pip install mujoco        # MuJoCo's own Python bindings, from PyPI
    python3 scripts/mujoco_poses.py

Elements without a name are written under the names the reader gives them (the guide's
descriptions page): `body<i>` for body id i and `joint<i>` for joint id i, MuJoCo's ids (its
order of the file's bodies and joints, the world body being 0), but for a model's one unnamed
free joint, `root_joint`; a site named like a body or joint is written as `NAME.site`.
"""

import json
import pathlib

import mujoco
import numpy as np

FIXTURES = pathlib.Path(__file__).resolve().parent.parent / "tests" / "fixtures" / "mujoco"


def name(model, kind, i, fallback):
    written = mujoco.mj_id2name(model, kind, i)
    return written if written else f"{fallback}{i}"


def configurations(model, count, rng):
    """The model's reference configuration, then random ones: hinges and slides within their range
    (or a turn either way when unlimited), free joints at random positions and orientations, ball
    joints at random orientations."""
    yield follow_equalities(model, model.qpos0.copy())
    for _ in range(count - 1):
        q = model.qpos0.copy()
        for j in range(model.njnt):
            a = model.jnt_qposadr[j]
            kind = model.jnt_type[j]
            if kind == mujoco.mjtJoint.mjJNT_FREE:
                quat = rng.normal(size=4)
                q[a : a + 7] = np.concatenate([rng.uniform(-1, 1, 3), quat / np.linalg.norm(quat)])
            elif kind == mujoco.mjtJoint.mjJNT_BALL:
                quat = rng.normal(size=4)
                q[a : a + 4] = quat / np.linalg.norm(quat)
            elif model.jnt_limited[j]:
                low, high = model.jnt_range[j]
                q[a] = rng.uniform(low, high)
            else:
                q[a] = rng.uniform(-np.pi, np.pi)
        yield follow_equalities(model, q)


def follow_equalities(model, q):
    """`q` with each joint an active joint equality couples set where the coupling puts it:
    MuJoCo's constraint `y - y0 = a0 + a1 (x - x0)` (y0, x0 the joints' qpos0), which kinematics
    alone does not enforce and the reader models as a mimic joint. Linear couplings only."""
    for e in range(model.neq):
        if model.eq_type[e] != mujoco.mjtEq.mjEQ_JOINT or not model.eq_active0[e] or model.eq_obj2id[e] < 0:
            continue
        y, x = model.jnt_qposadr[model.eq_obj1id[e]], model.jnt_qposadr[model.eq_obj2id[e]]
        a0, a1 = model.eq_data[e][0], model.eq_data[e][1]
        q[y] = model.qpos0[y] + a0 + a1 * (q[x] - model.qpos0[x])
    return q


def joint_names(model):
    """Each joint's name as the reader gives it."""
    names = [name(model, mujoco.mjtObj.mjOBJ_JOINT, j, "joint") for j in range(model.njnt)]
    unnamed_free = [
        j
        for j in range(model.njnt)
        if not mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, j) and model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE
    ]
    if len(unnamed_free) == 1 and "root_joint" not in names:
        names[unnamed_free[0]] = "root_joint"
    return names


def poses(path):
    model = mujoco.MjModel.from_xml_path(str(path))
    data = mujoco.MjData(model)
    names = joint_names(model)
    rng = np.random.default_rng(2026)
    out = []
    for q in configurations(model, 4, rng):
        data.qpos[:] = q
        mujoco.mj_kinematics(model, data)
        joints = {}
        for j in range(model.njnt):
            a = model.jnt_qposadr[j]
            width = {int(mujoco.mjtJoint.mjJNT_FREE): 7, int(mujoco.mjtJoint.mjJNT_BALL): 4}.get(int(model.jnt_type[j]), 1)
            joints[names[j]] = [float(v) for v in q[a : a + width]]
        frames = {}
        for b in range(1, model.nbody):
            frames[name(model, mujoco.mjtObj.mjOBJ_BODY, b, "body")] = frame(data.xpos[b], data.xmat[b])
        sites = {}
        bodies_and_joints = set(frames) | set(names)
        for s in range(model.nsite):
            written = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_SITE, s)
            if written:
                # A site named like a body or joint gives way, as the reader names it.
                link = f"{written}.site" if written in bodies_and_joints else written
                sites[link] = frame(data.site_xpos[s], data.site_xmat[s])
        out.append({"qpos": joints, "bodies": frames, "sites": sites})
    return {"mujoco": mujoco.__version__, "configurations": out}


def frame(pos, xmat):
    return {"pos": [float(v) for v in pos], "rows": [[float(v) for v in xmat[3 * i : 3 * i + 3]] for i in range(3)]}


def main():
    for path in sorted(FIXTURES.glob("*.xml")):
        target = path.with_suffix(".poses.json")
        target.write_text(json.dumps(poses(path), indent=1) + "\n")
        print(f"{target.relative_to(FIXTURES.parent.parent.parent)}")


if __name__ == "__main__":
    main()
