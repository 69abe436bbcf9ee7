#!/usr/bin/env python3
"""Writes cairn_humanoid.urdf, the project's WABIAN-2-sized biped (see README.md for the numbers' sources).

The URDF is generated so that every inertia is consistent with the link's mass and shape, the two sides are
exact mirror images and the totals can be checked; run `/usr/bin/python3 generate_cairn_humanoid.py` after
changing a number here and commit both files.
"""
import math
import os

# ---------------------------------------------------------------------------------------------------------
# Dimensions (metres) in the zero configuration: standing straight, arms hanging, x forward, y left, z up,
# the soles on z = 0.
ANKLE_HEIGHT = 0.10      # ankle joint axes above the sole
SHANK = 0.33             # knee to ankle
THIGH = 0.33             # hip pitch/roll centre to knee
HIP_YAW_ABOVE_HIP = 0.05 # hip yaw joint above the hip roll/pitch centre
HIP_Y = 0.08             # half the hip spacing
PELVIS_Z = ANKLE_HEIGHT + SHANK + THIGH + HIP_YAW_ABOVE_HIP + 0.05  # pelvis frame (root link) height: 0.86
WAIST_ABOVE_PELVIS = 0.10
SHOULDER_ABOVE_WAIST = 0.28
SHOULDER_Y = 0.21
UPPER_ARM = 0.25
FOREARM = 0.22
NECK_ABOVE_WAIST = 0.34
NECK_PITCH_ABOVE_YAW = 0.04
HEAD_RADIUS = 0.10
HEAD_CENTRE_ABOVE_NECK = 0.06
FOOT_LENGTH, FOOT_WIDTH, FOOT_THICKNESS = 0.24, 0.14, 0.03
FOOT_FORWARD = 0.03      # sole centre ahead of the ankle axis

# Masses (kg); 64.0 in total.
MASS = dict(pelvis=9.0, waist=1.0, torso=14.5, neck=0.5, head=3.0,
            hip_yaw=1.0, hip_roll=1.2, thigh=5.5, shank=3.5, ankle=0.6, foot=1.6,
            shoulder_pitch=0.5, shoulder_roll=0.5, upper_arm=1.6, forearm=1.0, wrist_yaw=0.3, wrist_pitch=0.2,
            hand=0.5)

# Limits: (lower, upper) rad, effort N m, velocity rad/s.
LIMITS = dict(
    hip_yaw=(-0.52, 0.52, 80, 6), hip_roll=(-0.35, 0.52, 150, 6), hip_pitch=(-1.75, 0.52, 200, 6),
    knee=(0.0, 2.27, 200, 6), ankle_pitch=(-0.87, 0.70, 120, 6), ankle_roll=(-0.35, 0.35, 100, 6),
    waist_yaw=(-0.78, 0.78, 100, 4), waist_roll=(-0.26, 0.26, 150, 4),
    shoulder_pitch=(-3.14, 1.05, 50, 5), shoulder_roll=(-0.17, 2.62, 50, 5), shoulder_yaw=(-1.57, 1.57, 30, 5),
    elbow=(-2.44, 0.0, 30, 5), wrist_yaw=(-1.57, 1.57, 10, 5), wrist_pitch=(-0.87, 0.87, 10, 5),
    wrist_roll=(-0.52, 0.52, 10, 5), neck_yaw=(-1.22, 1.22, 10, 4), neck_pitch=(-0.52, 0.70, 10, 4))


def box_inertia(m, x, y, z):
    return (m * (y * y + z * z) / 12, m * (x * x + z * z) / 12, m * (x * x + y * y) / 12)


def cylinder_inertia(m, r, h):  # axis z
    side = m * (3 * r * r + h * h) / 12
    return (side, side, m * r * r / 2)


def fmt(*values):
    return " ".join("%.6g" % (0.0 if abs(v) < 1e-12 else v) for v in values)


links, joints = [], []


def link(name, mass, com=(0, 0, 0), inertia=None, collisions=(), mass_key=None):
    xml = ['  <link name="%s">' % name]
    if mass is not None:
        ixx, iyy, izz = inertia
        xml.append('    <inertial><origin xyz="%s"/><mass value="%g"/>'
                   '<inertia ixx="%s" iyy="%s" izz="%s" ixy="0" ixz="0" iyz="0"/></inertial>'
                   % (fmt(*com), mass, fmt(ixx), fmt(iyy), fmt(izz)))
    for c in collisions:
        xml.append(c)
    xml.append('  </link>')
    links.append("\n".join(xml))


def collision(name, xyz, geometry, rpy=(0, 0, 0)):
    return ('    <collision name="%s"><origin xyz="%s" rpy="%s"/><geometry>%s</geometry></collision>'
            % (name, fmt(*xyz), fmt(*rpy), geometry))


def box(x, y, z):
    return '<box size="%s"/>' % fmt(x, y, z)


def capsule_geometry(radius, length):
    # Read as a capsule by Cairn (collision name starting with "capsule"); other tools see a cylinder.
    return '<cylinder radius="%g" length="%g"/>' % (radius, length)


def sphere(radius):
    return '<sphere radius="%g"/>' % radius


def joint(name, kind, parent, child, xyz, axis=None, limits=None):
    xml = '  <joint name="%s" type="%s"><parent link="%s"/><child link="%s"/><origin xyz="%s"/>' % (
        name, kind, parent, child, fmt(*xyz))
    if axis is not None:
        xml += '<axis xyz="%s"/>' % fmt(*axis)
    if limits is not None:
        lo, hi, effort, velocity = limits
        xml += '<limit lower="%g" upper="%g" effort="%g" velocity="%g"/>' % (lo, hi, effort, velocity)
    joints.append(xml + '</joint>')


# Pelvis (root) and upper body.
link('pelvis', MASS['pelvis'], (0, 0, 0), box_inertia(MASS['pelvis'], 0.18, 0.28, 0.14),
     [collision('pelvis_box', (0, 0, 0), box(0.18, 0.28, 0.14))])
link('waist_link', MASS['waist'], (0, 0, 0), box_inertia(MASS['waist'], 0.08, 0.08, 0.04))
joint('waist_yaw', 'revolute', 'pelvis', 'waist_link', (0, 0, WAIST_ABOVE_PELVIS), (0, 0, 1), LIMITS['waist_yaw'])
torso_h = 0.30
link('torso', MASS['torso'], (-0.02, 0, 0.16), box_inertia(MASS['torso'], 0.22, 0.26, torso_h),
     [collision('torso_box', (-0.02, 0, 0.16), box(0.22, 0.26, torso_h)),
      collision('backpack_box', (-0.16, 0, 0.16), box(0.08, 0.24, 0.24))])
joint('waist_roll', 'revolute', 'waist_link', 'torso', (0, 0, 0), (1, 0, 0), LIMITS['waist_roll'])
link('neck_link', MASS['neck'], (0, 0, 0.02), cylinder_inertia(MASS['neck'], 0.03, 0.04))
joint('neck_yaw', 'revolute', 'torso', 'neck_link', (0, 0, NECK_ABOVE_WAIST), (0, 0, 1), LIMITS['neck_yaw'])
link('head', MASS['head'], (0, 0, HEAD_CENTRE_ABOVE_NECK),
     tuple(0.4 * MASS['head'] * HEAD_RADIUS ** 2 for _ in range(3)),
     [collision('head_sphere', (0, 0, HEAD_CENTRE_ABOVE_NECK), sphere(HEAD_RADIUS))])
joint('neck_pitch', 'revolute', 'neck_link', 'head', (0, 0, NECK_PITCH_ABOVE_YAW), (0, 1, 0), LIMITS['neck_pitch'])
link('head_camera', None)
joint('head_camera_joint', 'fixed', 'head', 'head_camera', (0.09, 0, HEAD_CENTRE_ABOVE_NECK))

for side, s in (('l', 1.0), ('r', -1.0)):
    # Arm: shoulder pitch (y), roll (x), yaw (z), elbow pitch (y), wrist yaw (z), pitch (y), roll (x).
    link('%s_shoulder_pitch_link' % side, MASS['shoulder_pitch'], (0, 0, 0),
         box_inertia(MASS['shoulder_pitch'], 0.06, 0.06, 0.06))
    joint('%s_shoulder_pitch' % side, 'revolute', 'torso', '%s_shoulder_pitch_link' % side,
          (0, s * SHOULDER_Y, SHOULDER_ABOVE_WAIST), (0, 1, 0), LIMITS['shoulder_pitch'])
    link('%s_shoulder_roll_link' % side, MASS['shoulder_roll'], (0, 0, 0),
         box_inertia(MASS['shoulder_roll'], 0.06, 0.06, 0.06),
         [collision('%s_shoulder_sphere' % side, (0, 0, 0), sphere(0.06))])
    joint('%s_shoulder_roll' % side, 'revolute', '%s_shoulder_pitch_link' % side, '%s_shoulder_roll_link' % side,
          (0, 0, 0), (s, 0, 0), LIMITS['shoulder_roll'])
    link('%s_upper_arm' % side, MASS['upper_arm'], (0, 0, -UPPER_ARM / 2),
         cylinder_inertia(MASS['upper_arm'], 0.045, UPPER_ARM),
         [collision('capsule_%s_upper_arm' % side, (0, 0, -UPPER_ARM / 2), capsule_geometry(0.045, UPPER_ARM - 0.09))])
    joint('%s_shoulder_yaw' % side, 'revolute', '%s_shoulder_roll_link' % side, '%s_upper_arm' % side,
          (0, 0, 0), (0, 0, s), LIMITS['shoulder_yaw'])
    link('%s_forearm' % side, MASS['forearm'], (0, 0, -FOREARM / 2), cylinder_inertia(MASS['forearm'], 0.04, FOREARM),
         [collision('capsule_%s_forearm' % side, (0, 0, -FOREARM / 2), capsule_geometry(0.04, FOREARM - 0.08))])
    joint('%s_elbow' % side, 'revolute', '%s_upper_arm' % side, '%s_forearm' % side, (0, 0, -UPPER_ARM),
          (0, 1, 0), LIMITS['elbow'])
    link('%s_wrist_yaw_link' % side, MASS['wrist_yaw'], (0, 0, 0), box_inertia(MASS['wrist_yaw'], 0.04, 0.04, 0.04))
    joint('%s_wrist_yaw' % side, 'revolute', '%s_forearm' % side, '%s_wrist_yaw_link' % side, (0, 0, -FOREARM),
          (0, 0, s), LIMITS['wrist_yaw'])
    link('%s_wrist_pitch_link' % side, MASS['wrist_pitch'], (0, 0, 0),
         box_inertia(MASS['wrist_pitch'], 0.04, 0.04, 0.04))
    joint('%s_wrist_pitch' % side, 'revolute', '%s_wrist_yaw_link' % side, '%s_wrist_pitch_link' % side, (0, 0, 0),
          (0, 1, 0), LIMITS['wrist_pitch'])
    link('%s_hand' % side, MASS['hand'], (0, 0, -0.06), box_inertia(MASS['hand'], 0.05, 0.08, 0.12),
         [collision('%s_hand_sphere' % side, (0, 0, -0.06), sphere(0.045))])
    joint('%s_wrist_roll' % side, 'revolute', '%s_wrist_pitch_link' % side, '%s_hand' % side, (0, 0, 0),
          (s, 0, 0), LIMITS['wrist_roll'])
    link('%s_palm' % side, None)
    joint('%s_palm_joint' % side, 'fixed', '%s_hand' % side, '%s_palm' % side, (0, 0, -0.08))

    # Leg: hip yaw (z), roll (x), pitch (y), knee pitch (y), ankle pitch (y), roll (x).
    link('%s_hip_yaw_link' % side, MASS['hip_yaw'], (0, 0, 0), box_inertia(MASS['hip_yaw'], 0.08, 0.08, 0.06))
    joint('%s_hip_yaw' % side, 'revolute', 'pelvis', '%s_hip_yaw_link' % side,
          (0, s * HIP_Y, -(PELVIS_Z - ANKLE_HEIGHT - SHANK - THIGH - HIP_YAW_ABOVE_HIP)), (0, 0, s),
          LIMITS['hip_yaw'])
    link('%s_hip_roll_link' % side, MASS['hip_roll'], (0, 0, 0), box_inertia(MASS['hip_roll'], 0.08, 0.08, 0.08))
    joint('%s_hip_roll' % side, 'revolute', '%s_hip_yaw_link' % side, '%s_hip_roll_link' % side,
          (0, 0, -HIP_YAW_ABOVE_HIP), (s, 0, 0), LIMITS['hip_roll'])
    link('%s_thigh' % side, MASS['thigh'], (0, 0, -THIGH / 2), cylinder_inertia(MASS['thigh'], 0.07, THIGH),
         [collision('capsule_%s_thigh' % side, (0, 0, -THIGH / 2), capsule_geometry(0.07, THIGH - 0.14))])
    joint('%s_hip_pitch' % side, 'revolute', '%s_hip_roll_link' % side, '%s_thigh' % side, (0, 0, 0), (0, 1, 0),
          LIMITS['hip_pitch'])
    link('%s_shank' % side, MASS['shank'], (0, 0, -SHANK / 2), cylinder_inertia(MASS['shank'], 0.055, SHANK),
         [collision('capsule_%s_shank' % side, (0, 0, -SHANK / 2), capsule_geometry(0.055, SHANK - 0.11))])
    joint('%s_knee' % side, 'revolute', '%s_thigh' % side, '%s_shank' % side, (0, 0, -THIGH), (0, 1, 0),
          LIMITS['knee'])
    link('%s_ankle_link' % side, MASS['ankle'], (0, 0, 0), box_inertia(MASS['ankle'], 0.06, 0.06, 0.06))
    joint('%s_ankle_pitch' % side, 'revolute', '%s_shank' % side, '%s_ankle_link' % side, (0, 0, -SHANK), (0, 1, 0),
          LIMITS['ankle_pitch'])
    foot_centre = (FOOT_FORWARD, 0, -ANKLE_HEIGHT + FOOT_THICKNESS / 2)
    link('%s_foot' % side, MASS['foot'], (FOOT_FORWARD, 0, -0.06),
         box_inertia(MASS['foot'], FOOT_LENGTH, FOOT_WIDTH, 0.08),
         [collision('%s_sole_box' % side, foot_centre, box(FOOT_LENGTH, FOOT_WIDTH, FOOT_THICKNESS)),
          collision('%s_ankle_box' % side, (0, 0, -0.05), box(0.10, 0.10, 0.06))])
    joint('%s_ankle_roll' % side, 'revolute', '%s_ankle_link' % side, '%s_foot' % side, (0, 0, 0), (s, 0, 0),
          LIMITS['ankle_roll'])
    link('%s_sole' % side, None)
    joint('%s_sole_joint' % side, 'fixed', '%s_foot' % side, '%s_sole' % side, (FOOT_FORWARD, 0, -ANKLE_HEIGHT))

total = MASS['pelvis'] + MASS['waist'] + MASS['torso'] + MASS['neck'] + MASS['head'] + 2 * sum(
    MASS[k] for k in ('shoulder_pitch', 'shoulder_roll', 'upper_arm', 'forearm', 'wrist_yaw', 'wrist_pitch', 'hand',
                      'hip_yaw', 'hip_roll', 'thigh', 'shank', 'ankle', 'foot'))
assert abs(total - 64.0) < 1e-9, total

header = """<?xml version="1.0"?>
<!-- Cairn's humanoid: a WABIAN-2-sized biped (1.50 m, %.1f kg, 30 joints). Generated by
     generate_cairn_humanoid.py; edit that script, not this file. Dimensions and sources: README.md.
     Collision cylinders whose name starts with "capsule" are capsules (cap centres `length` apart). -->
<robot name="cairn_humanoid">
""" % total
path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cairn_humanoid.urdf")
with open(path, "w") as out:
    out.write(header + "\n".join(links) + "\n" + "\n".join(joints) + "\n</robot>\n")
print("wrote %s: %d links, %d joints, %.1f kg" % (path, len(links), len(joints), total))
