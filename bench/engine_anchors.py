"""The frame-based anchors of bench/engine.py: pymunk (Chipmunk2D) and Box2D, built from the same
engine_scenes.Scene and driven the same way.

Each engine keeps its own defaults except where the scene says otherwise (restitution, zero
friction, no damping, no sleeping; the stacking scenes, `Scene.rest`: friction, sleeping, and for
pymunk a collision slop of 5 mm, Box2D's linear slop, as its default 0.1 is meant for pixels): pymunk 10 iterations, collision slop 0.1; Box2D 8 velocity and
3 position iterations, continuous collision on (it is Box2D's default, and covers dynamic bodies
against static ones; `bullet` is not set).

Where they cannot model exactly the scene (said in the results too):
* Box2D gives every polygon and edge a skin of b2_polygonRadius = 0.01 m: a disc touches a wall
  0.01 m early, and a polygon touches a wall 0.01 m early.
* Box2D ignores restitution below b2_velocityThreshold = 1 m/s of closing speed (the contact is
  then inelastic), and moves no body more than b2_maxTranslation = 2 m in one step.
* Box2D mixes restitution as max(e1, e2), pymunk as e1 * e2: with e = 1 everywhere (all scenes
  here) both give 1.

Contact times. An engine knows of a contact at the time of the state in which it found it; that is
the time recorded:
* pymunk finds contacts after moving the bodies: the end of the step;
* Box2D finds them at the start of the step, on the positions the previous step left (the end of
  the previous step), except for contacts found by its continuous (time-of-impact) pass, which
  leaves the body at the impact pose at the end of the step: the end of the step.
"""

from __future__ import annotations

import math

from engine_scenes import Block, Disc, Scene


class PymunkSim:
    def __init__(self, scene: Scene, dt: float, record: bool) -> None:
        import pymunk
        self.dt, self.now, self.steps = dt, 0.0, 0
        self.contacts: list[tuple[float, int, int]] = []
        space = pymunk.Space()
        space.gravity = scene.gravity
        if scene.rest:      # stacking: bodies may sleep, and a slop fit for metres (Box2D's 5 mm)
            space.sleep_time_threshold = 0.5
            space.collision_slop = 0.005
        index = {}
        for k, wall in enumerate(scene.walls):
            seg = pymunk.Segment(space.static_body, wall.a, wall.b, 0.0)
            seg.friction, seg.elasticity = scene.coefficients(wall.e, "product", "product")
            space.add(seg)
            index[seg] = -(k + 1)
        self.bodies = []
        for i, b in enumerate(scene.bodies):
            body = pymunk.Body(b.m, b.moment)
            body.position, body.velocity = (b.x, b.y), (b.vx, b.vy)
            body.angle, body.angular_velocity = b.angle, b.w
            if isinstance(b, Disc):
                shape = pymunk.Circle(body, b.r)
            else:
                assert isinstance(b, Block)
                shape = pymunk.Poly(body, b.vertices, radius=0.0)
            shape.friction, shape.elasticity = scene.coefficients(b.e, "product", "product")
            space.add(body, shape)
            index[shape] = i
            self.bodies.append(body)
        if record:
            def begin(arbiter, _space, _data) -> None:
                i, j = sorted(index[s] for s in arbiter.shapes)
                self.contacts.append((self.now + self.dt, i, j))
            space.on_collision(begin=begin)
        self.space = space

    def advance(self, t_end: float) -> None:
        """Whole steps until the time reaches t_end (within a millionth of a step)."""
        step, dt = self.space.step, self.dt
        n = max(0, math.ceil((t_end - self.now) / dt - 1e-6))
        for _ in range(n):
            step(dt)
            self.now += dt
        self.steps += n

    def states(self) -> list[tuple[float, float, float, float, float, float]]:
        return [(b.position.x, b.position.y, b.angle, b.velocity.x, b.velocity.y, b.angular_velocity)
                for b in self.bodies]

    def poses(self) -> list[tuple[float, float, float]]:
        """Every body's pose now: what a frame draws."""
        return [(b.position.x, b.position.y, b.angle) for b in self.bodies]


class Box2DSim:
    VELOCITY_ITERATIONS = 8
    POSITION_ITERATIONS = 3

    def __init__(self, scene: Scene, dt: float, record: bool) -> None:
        import Box2D
        self.dt, self.now, self.steps = dt, 0.0, 0
        self.contacts: list[tuple[float, int, int]] = []
        world = Box2D.b2World(gravity=scene.gravity, doSleep=scene.rest)
        world.continuousPhysics = True
        if scene.walls:
            ground = world.CreateStaticBody()
            for k, wall in enumerate(scene.walls):
                mu, e = scene.coefficients(wall.e, "sqrt", "max")
                fx = ground.CreateEdgeFixture(vertices=[wall.a, wall.b], friction=mu, restitution=e)
                fx.userData = -(k + 1)
        self.bodies = []
        for i, b in enumerate(scene.bodies):
            body = world.CreateDynamicBody(position=(b.x, b.y), angle=b.angle, linearVelocity=(b.vx, b.vy),
                                           angularVelocity=b.w, linearDamping=0.0, angularDamping=0.0,
                                           allowSleep=scene.rest)
            mu, e = scene.coefficients(b.e, "sqrt", "max")
            if isinstance(b, Disc):
                fx = body.CreateCircleFixture(radius=b.r, density=b.m / (math.pi * b.r * b.r),
                                              friction=mu, restitution=e)
            else:
                fx = body.CreatePolygonFixture(vertices=list(b.vertices), density=b.m / b.area,
                                               friction=mu, restitution=e)
            fx.userData = i
            self.bodies.append(body)
        self.world = world
        self.start: list[tuple[float, float]] | None = None
        if record:
            sim = self

            class Listener(Box2D.b2ContactListener):
                def BeginContact(self, contact) -> None:  # noqa: N802 (Box2D's name)
                    i, j = sorted((contact.fixtureA.userData, contact.fixtureB.userData))
                    moved = any(k >= 0 and tuple(sim.bodies[k].position) != sim.start[k] for k in (i, j))
                    sim.contacts.append((sim.now + (sim.dt if moved else 0.0), i, j))

            self.listener = Listener()
            world.contactListener = self.listener

    def advance(self, t_end: float) -> None:
        step, dt = self.world.Step, self.dt
        vi, pi = self.VELOCITY_ITERATIONS, self.POSITION_ITERATIONS
        n = max(0, math.ceil((t_end - self.now) / dt - 1e-6))
        recording = hasattr(self, "listener")
        for _ in range(n):
            if recording:
                self.start = [tuple(b.position) for b in self.bodies]
            step(dt, vi, pi)
            self.now += dt
        self.steps += n

    def states(self) -> list[tuple[float, float, float, float, float, float]]:
        out = []
        for b in self.bodies:
            p, v = b.position, b.linearVelocity
            out.append((p[0], p[1], b.angle, v[0], v[1], b.angularVelocity))
        return out

    def poses(self) -> list[tuple[float, float, float]]:
        """Every body's pose now: what a frame draws."""
        return [(b.position[0], b.position[1], b.angle) for b in self.bodies]


class Anchor:
    """A frame-based engine at one time step."""

    def __init__(self, name: str, sim: type, dt: float) -> None:
        self.name, self.sim, self.dt = name, sim, dt
        self.label = f"{name} 1/{round(1 / dt)}"

    def build(self, scene: Scene, record: bool = False):
        return self.sim(scene, self.dt, record)


def versions() -> dict[str, str]:
    import Box2D
    import pymunk
    return {"pymunk": pymunk.version, "chipmunk": pymunk.chipmunk_version.split("-")[0],
            "Box2D": Box2D.__version__}


def anchors(dts=(1 / 60, 1 / 240)) -> list[Anchor]:
    return [Anchor(name, sim, dt) for dt in dts for name, sim in (("pymunk", PymunkSim), ("Box2D", Box2DSim))]
