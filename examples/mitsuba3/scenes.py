"""The three comparison scenes as Mitsuba 3 dicts (the same geometry as apse's demo, y up).

    plane   : a disk light perpendicular to a diffuse ground plane (`path`)
    medium  : a disk light inside a box of homogeneous medium (`volpath`)
    sphere  : a sphere light half-buried in a diffuse ground plane, in front of a diffuse wall
              (`path`; sphere_scene_dict: Mitsuba's sphere + area light or apse_sphere)
    spheres : the authors' scene: three diffuse spheres of radius 2 on a plane, a two-sided disk
              light of radius 3 at (1, 3, 4) (`path`); seen from the side, because Mitsuba's
              lights are visible to camera rays and the demo's viewpoint looks through the light
    room    : a realistic case rather than a best one: a closed diffuse room (floor, ceiling,
              three walls and the wall behind the camera), a glossy sphere (rough plastic), a
              diffuse sphere and a close disk light tilted towards them, path traced to depth 4
              (three bounces: most of the picture is lit indirectly, and the glossy sphere's
              highlights come from BSDF samples)

Every light is a `disk` shape with a black BSDF (it only emits), two-sided by default as in the
demo, carrying apse's `apse_disk` emitter with the named sampler ("area" is uniform sampling by
area through the disk shape, exactly Mitsuba's own disk light) or, for light="mitsuba", Mitsuba's
own `area` emitter. Mitsuba 3.9.1's `area` emitter is one-sided, so a two-sided "mitsuba" light is
two back-to-back disks (what a Mitsuba user would write; the back one 1e-4 radii behind, since
coplanar disks would shadow each other): half of its samples go to the disk facing away, which
apse_disk's "area" mode avoids.
"""
import math

import mitsuba as mi

SCENES = ("plane", "medium", "spheres", "room")
APSE_SAMPLERS = ("radial", "ld_radial", "parallel", "tabulated_ld_radial", "cosine_ld_radial",
                 "cosine_tabulated_ld_radial")
LIGHTS = ("mitsuba", "area") + APSE_SAMPLERS

T = mi.ScalarTransform4f


def _disks(center, normal, radius, radiance, light, twosided, standalone=False, aspect=1.0):
    """{key: disk shape or emitter} of the disk light; `light` is "mitsuba" or an apse_disk
    sampler name. standalone=True: a black disk shape without emitter (for the same occlusion)
    plus a standalone apse_disk emitter (center/normal/radius) in its place."""
    if light == "mitsuba":
        emitter = {"type": "area"}
    else:
        emitter = {"type": "apse_disk", "sampler": light, "twosided": twosided}
    emitter["radiance"] = {"type": "rgb", "value": radiance}
    c = mi.ScalarPoint3f(center)
    n = mi.ScalarVector3f(normal)
    # look_at points the disk's +z (its normal) along n; any up vector not parallel to n
    up = [0, 1, 0] if abs(n[1]) < 0.9 * math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2) else [1, 0, 0]
    to_world = T().look_at(origin=c, target=c + n, up=up) @ T().scale([radius, aspect * radius, radius])
    disk = {"type": "disk", "to_world": to_world, "emitter": emitter,
            "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": 0.0}}}
    if standalone:
        if aspect != 1.0:
            raise ValueError("a standalone apse_disk light is a disk (aspect 1)")
        del disk["emitter"]
        return {"light": disk, "light_emitter": dict(emitter, center=c, normal=n, radius=float(radius))}
    if light != "mitsuba" or not twosided:
        return {"light": disk}
    back = T().translate(-1e-4 * radius * n / math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2)) @ to_world
    return {"light": disk, "light_back": dict(disk, to_world=back, flip_normals=True, emitter=dict(emitter))}


def _camera(eye, target, fov, width, height, spp, sampler, seed):
    return {"type": "perspective", "fov": fov, "fov_axis": "y",
            "to_world": T().look_at(origin=eye, target=target, up=[0, 1, 0]),
            "film": {"type": "hdrfilm", "width": width, "height": height,
                     "rfilter": {"type": "box"}, "pixel_format": "rgb"},
            "sampler": {"type": sampler, "sample_count": spp, "seed": seed}}


def _integrator(kind, max_depth):
    return {"type": kind} if kind == "direct" else {"type": kind, "max_depth": max_depth}


def _ground():
    return {"type": "rectangle", "to_world": T().rotate([1, 0, 0], -90) @ T().scale(100),
            "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": 0.8}}}


def scene_dict(name, light, width=128, height=96, spp=16, sampler="stratified", seed=0,
               integrator=None, twosided=True, hide_emitters=False, standalone=False, aspect=1.0):
    """The Mitsuba scene dict of scene `name` lit by `light` (see module comment), rendered at
    width x height with `spp` samples per pixel of the given Mitsuba sampler. `integrator`
    overrides the scene's own (e.g. "direct"); twosided=False makes the light one-sided (emitting
    along its normal); hide_emitters=True renders directly visible lights black (they still
    occlude), so that image errors measure light sampling rather than the anti-aliasing of the
    light's bright silhouette, which is the same for every sampler; standalone=True places an
    apse_disk light by center/normal/radius instead of attaching it to the disk (see _disks);
    aspect != 1 squeezes the disk into an ellipse (semi-axes radius and aspect * radius)."""
    diffuse = {"type": "diffuse", "reflectance": {"type": "rgb", "value": 0.8}}
    if name == "plane":
        d = {"type": "scene",
             "integrator": _integrator(integrator or "path", 3),
             "sensor": _camera([0.3, 3.2, 5.5], [0.0, 0.2, 0.0], 50, width, height, spp, sampler, seed),
             "ground": _ground(),
             **_disks([0.0, 1.05, 0.0], [1.0, 0.0, 0.35], 1.0, 6.0, light, twosided, standalone, aspect)}
    elif name == "medium":
        d = {"type": "scene",
             "integrator": _integrator(integrator or "volpath", 4),
             "fog": {"type": "homogeneous", "sigma_t": 0.3, "albedo": 0.25 / 0.3},
             "sensor": _camera([0.0, 0.6, 5.0], [0.0, 0.0, 0.0], 45, width, height, spp, sampler, seed),
             "box": {"type": "cube", "to_world": T().scale(3.0), "bsdf": {"type": "null"},
                     "interior": {"type": "ref", "id": "fog"}},
             **_disks([0.0, 0.0, 0.0], [1.0, 0.25, 0.5], 1.0, 12.0, light, twosided, standalone, aspect)}
        for key in ("light", "light_back"):  # the light sits inside the medium on both sides
            if key in d:
                d[key]["interior"] = {"type": "ref", "id": "fog"}
                d[key]["exterior"] = {"type": "ref", "id": "fog"}
    elif name == "spheres":
        d = {"type": "scene",
             "integrator": _integrator(integrator or "path", 3),
             "sensor": _camera([18.0, 8.0, 14.0], [1.0, 1.0, -1.0], 50, width, height, spp, sampler, seed),
             "ground": _ground(),
             **_disks([1.0, 3.0, 4.0], [0.0, -1.0, -1.0], 3.0, 1.5, light, twosided, standalone, aspect)}
        for i, c in enumerate(([-4.0, 2.0, -0.5], [1.0, 2.0, -3.0], [6.0, 2.0, -0.5])):
            d["sphere%d" % i] = {"type": "sphere", "center": c, "radius": 2.0, "bsdf": diffuse}
    elif name == "room":
        grey = {"type": "diffuse", "reflectance": {"type": "rgb", "value": 0.6}}
        d = {"type": "scene",
             "integrator": _integrator(integrator or "path", 4),
             "sensor": _camera([0.0, 1.3, 3.6], [0.0, 0.8, 0.0], 55, width, height, spp, sampler, seed),
             **_disks([-0.7, 1.7, 0.3], [0.5, -1.0, -0.2], 0.45, 8.0, light, twosided, standalone, aspect)}
        # the room [-2, 2] x [0, 2.5] x [-2, 4]: six rectangles (Mitsuba's: [-1, 1]^2 in z = 0, facing
        # +z) facing inwards: (centre, rotation, half extents)
        walls = {"floor": ([0.0, 0.0, 1.0], T().rotate([1, 0, 0], -90), [2.0, 3.0]),
                 "ceiling": ([0.0, 2.5, 1.0], T().rotate([1, 0, 0], 90), [2.0, 3.0]),
                 "back": ([0.0, 1.25, -2.0], T(), [2.0, 1.25]),
                 "front": ([0.0, 1.25, 4.0], T().rotate([0, 1, 0], 180), [2.0, 1.25]),
                 "left": ([-2.0, 1.25, 1.0], T().rotate([0, 1, 0], 90), [3.0, 1.25]),
                 "right": ([2.0, 1.25, 1.0], T().rotate([0, 1, 0], -90), [3.0, 1.25])}
        for key, (center, rotation, half) in walls.items():
            d[key] = {"type": "rectangle", "bsdf": grey,
                      "to_world": T().translate(center) @ rotation @ T().scale([half[0], half[1], 1.0])}
        d["glossy"] = {"type": "sphere", "center": [0.45, 0.55, -0.3], "radius": 0.55,
                       "bsdf": {"type": "roughplastic", "distribution": "ggx", "alpha": 0.08,
                                "diffuse_reflectance": {"type": "rgb", "value": 0.15}}}
        d["ball"] = {"type": "sphere", "center": [-0.6, 0.35, 0.5], "radius": 0.35, "bsdf": grey}
    else:
        raise ValueError("unknown scene " + name)
    if hide_emitters:
        d["integrator"]["hide_emitters"] = True
    return d


def sphere_scene_dict(light, width=64, height=48, spp=16, sampler="stratified", seed=0, integrator="path",
                      hide_emitters=False, standalone=False):
    """The `sphere` scene lit by `light`: "mitsuba" (a sphere shape with Mitsuba's own `area`
    emitter, which samples the cone the sphere subtends uniformly) or an apse_sphere sampler name
    ("area" is the sphere shape's own sampling through apse_sphere, exactly Mitsuba's light).
    A sphere of radius 0.8 and radiance 4 at (0, 0.5, 0) sinks 0.3 into the ground (y = 0), so
    from every point of the ground it straddles the horizon (the cosine_* samplers use the plain
    map there); a wall at z = -1, facing +z, 0.2 behind the sphere, sees all of it above its
    horizon, close enough for the cosine to vary much across it. standalone=True: a standalone
    apse_sphere (center, radius) and no sphere shape. With hide_emitters and `direct` that renders
    the attached light's image (in expectation): Mitsuba 3.9.1 lets camera rays pass through
    hidden emitters, and a convex light never hides its own samples; a black sphere left in its
    place would not be passed through. Other arguments as scene_dict."""
    center, radius = [0.0, 0.5, 0.0], 0.8
    emitter = {"type": "area"} if light == "mitsuba" else {"type": "apse_sphere", "sampler": light}
    emitter["radiance"] = {"type": "rgb", "value": 4.0}
    ball = {"type": "sphere", "center": center, "radius": radius, "emitter": emitter,
            "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": 0.0}}}
    d = {"type": "scene",
         "integrator": _integrator(integrator, 3),
         "sensor": _camera([0.6, 2.4, 4.5], [0.0, 0.4, -0.6], 55, width, height, spp, sampler, seed),
         "ground": _ground(),
         "wall": {"type": "rectangle", "to_world": T().translate([0.0, 0.0, -1.0]) @ T().scale(100),
                  "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": 0.8}}},
         "light": ball}
    if standalone:
        del d["light"]
        d["light_emitter"] = dict(emitter, center=mi.ScalarPoint3f(center), radius=radius)
    if hide_emitters:
        d["integrator"]["hide_emitters"] = True
    return d
