using System.Numerics;
using AcDream.App.Movement;
using AcDream.App.World;
using AcDream.Core.Physics;

namespace AcDream.App.Scenes;

/// <summary>
/// Runs a scene: a <see cref="GameWindow"/> streams the Holtburg world around the mover, and a
/// <see cref="PlayerMovementMode"/> walks the legs at a fixed 30 Hz. The loader thread is real; each
/// frame the runner waits for the loads requested in that frame before the next one, so every run
/// of a scene gives the same frames.
/// </summary>
/// <remarks>
/// The player is a mover (<see cref="PlayerId"/>, a cylinder of its body, <see cref="MoverState.Player"/>); the scene's
/// creatures (<see cref="FirstCreatureId"/> on) and doors appear with their landblock and leave with it. Each frame:
/// streaming, the leg's door action (on its first frame), one commit of the movers (<see cref="GameWindow.CommitMovers"/>),
/// the player's move, then each creature's, each resolved by the engine with its own id against the movers as committed
/// at the frame's start; a creature whose answer ends inside a mover that has already moved this frame (the player, or
/// a creature before it) stays where it was for the frame (<see cref="Creature.HoldBack"/>). Then every mover is moved
/// to where it ended, for the next frame's commit. After the player's move a chase camera (<see cref="ChaseCamera"/>)
/// places its eye behind the player (<see cref="FrameSample.Camera"/>; at the start too), and after a leg's last frame
/// the scene's pointer rays for that leg are cast (<see cref="Pointer"/>, <see cref="WalkRecord.Pointers"/>).
/// </remarks>
internal static class SceneRunner
{
    /// <summary>Simulation rate: 30 frames per second.</summary>
    public const int FramesPerSecond = 30;

    /// <summary>A point leg ends when the mover is this close to its point, metres.</summary>
    public const float ArrivalDistance = 0.01f;

    /// <summary>The player's mover id: 0x50000001, the game's first player id.</summary>
    public const uint PlayerId = 0x50000001;

    /// <summary>The first creature's mover id: 0x80000001 (the game numbers the objects it creates from 0x80000000); creature i of a scene is 0x80000001 + i.</summary>
    public const uint FirstCreatureId = 0x80000001;

    /// <summary>Longest wait for one frame's landblock loads before the run gives up: 30 s.</summary>
    private static readonly TimeSpan LoadTimeout = TimeSpan.FromSeconds(30);

    /// <summary>Runs <paramref name="scene"/> in its own world (<see cref="Scene.CreateWorld"/>).</summary>
    public static WalkRecord Run(Scene scene, int? maxFrames = null) => Run(scene, scene.CreateWorld(), maxFrames);

    /// <summary>
    /// Runs <paramref name="scene"/>; stops after <paramref name="maxFrames"/> frames if given; <paramref name="recorder"/>, if
    /// given, sees every call of its engine; <paramref name="drawing"/>, if given, receives what each of the player's moves
    /// saw (the answers are the same either way).
    /// </summary>
    /// <exception cref="ArgumentException"><paramref name="world"/> is not the scene's world with its objects.</exception>
    public static WalkRecord Run(Scene scene, HoltburgWorld world, int? maxFrames = null, IEngineRecorder? recorder = null, FrameDrawing? drawing = null)
    {
        if (!world.Is(scene.World, scene.Objects ?? []))
        {
            throw new ArgumentException($"the scene walks the {scene.World} world with objects [{string.Join(", ", scene.Objects ?? [])}]; this world is {world.World} with [{string.Join(", ", world.Objects)}].", nameof(world));
        }

        const float dt = 1f / FramesPerSecond;
        var warnings = new List<string>();
        var streaming = new List<StreamingEvent>();
        var samples = new List<FrameSample>();
        var legs = new List<LegResult>();
        var drops = new List<Drop>();
        var touches = new List<MoverTouch>();
        var doorChanges = new List<DoorChange>();
        var pointers = new List<PointerResult>();
        var creatures = (scene.Creatures ?? []).Select((c, i) => new Creature(FirstCreatureId + (uint)i, c)).ToList();
        var doors = (scene.Doors ?? []).Select(name => world.Doors[name]).ToList();
        var doorsIn = new HashSet<uint>(); // the doors registered now
        var doorStates = new Dictionary<uint, DoorState>(); // each registered door's last recorded state
        MoverShape creatureShape = MoverShape.Cylinder(MoverBody.Player.Radius, MoverBody.Player.Height);
        int frame = 0;

        using var window = new GameWindow(world, world.HeightTable, world.Center, warnings.Add);
        PhysicsEngine engine = window.Physics;
        engine.Recorder = recorder;
        window.LandblockLoaded += id =>
        {
            streaming.Add(new StreamingEvent(frame, id, true, window.ObjectCounts.GetValueOrDefault(id)));
            Populate(id);
        };
        window.LandblockUnloaded += id =>
        {
            streaming.Add(new StreamingEvent(frame, id, false));
            Depopulate(id);
        };

        var startXY = new Vector3(scene.Start, 0f);
        window.UpdateStreaming(startXY);
        Wait(window);
        window.UpdateStreaming(startXY);
        ResolveResult start = StartOnGround(startXY, engine);

        var mode = new PlayerMovementMode(engine, start.Position, start.CellId, scene.StartHeadingDegrees * (MathF.PI / 180f), scene.Effects) { MoverId = PlayerId };
        mode.Character.DebugSink = drawing;
        MoverBody playerBody = scene.Effects.Body ?? MoverBody.Player;
        window.AddMover(PlayerId, MoverShape.Cylinder(playerBody.Radius, playerBody.Height), start.Position, start.CellId, Facing(mode.Heading), MoverState.Player);
        window.CommitMovers();
        RecordDoors();
        var camera = new ChaseCamera(engine, PlayerId);
        var pointer = new Pointer(engine, PlayerId);
        samples.Add(new FrameSample(0, start.Position, start.CellId, start.IsOnGround, null, Camera: camera.Update(mode.Position, mode.CellId, mode.Heading)));

        bool truncated = false;
        foreach (SceneLeg leg in scene.Legs)
        {
            int first = frame + 1;
            int limit = (int)MathF.Round(leg.Seconds * FramesPerSecond);
            var refusals = new Dictionary<ResolveOutcome, int>();
            var slides = new List<Vector3>();
            bool reached = false;
            mode.JumpSkill = leg.JumpSkill;
            (int Jumps, int HeadHits, int Landings, int EdgeSlides) air = default;
            DoorAction(leg);
            for (int n = 0; ; n++)
            {
                MovementIntent intent;
                if (leg.To is Vector2 to)
                {
                    Vector2 away = to - new Vector2(mode.Position.X, mode.Position.Y);
                    float distance = away.Length();
                    if (distance <= ArrivalDistance && mode.IsOnGround)
                    {
                        reached = true;
                        break;
                    }

                    if (n >= limit)
                    {
                        break;
                    }

                    // There in the air: wait to come down, not moving across.
                    mode.Heading = distance > ArrivalDistance ? MathF.Atan2(away.X, away.Y) + (leg.Backward ? MathF.PI : 0f) : mode.Heading;
                    float stepLength = (leg.Run ? PlayerMovementMode.RunSpeed : PlayerMovementMode.WalkSpeed) * dt;
                    float speed = MathF.Min(1f, distance / stepLength);
                    intent = new MovementIntent(leg.Backward ? -speed : speed, 0f, 0f, leg.Run, leg.Jump && n == 0);
                }
                else
                {
                    if (n >= limit)
                    {
                        reached = true;
                        break;
                    }

                    intent = new MovementIntent(leg.Forward, leg.Strafe, leg.Turn, leg.Run, leg.Jump && n == 0);
                }

                if (maxFrames is int max && frame >= max)
                {
                    truncated = true;
                    break;
                }

                frame++;
                window.UpdateStreaming(mode.Position);
                Wait(window);
                window.CommitMovers();
                RecordDoors();
                FrameSample before = samples[^1];
                drawing?.Frame = frame;
                CharacterStep moved = mode.Update(intent, dt);
                foreach (uint id in mode.Touched)
                {
                    touches.Add(new MoverTouch(frame, id, moved.Met.Wall.Kind == SurfaceKind.Mover && moved.Met.Wall.Id == id));
                }

                StepCreatures(mode);
                window.MoveMover(PlayerId, mode.Position, mode.CellId, Facing(mode.Heading));
                if (moved.LastRefusal is ResolveOutcome refusal)
                {
                    refusals[refusal] = refusals.GetValueOrDefault(refusal) + 1;
                }

                Vector3? slide = moved.SlidSteps > 0 ? moved.LastSlideNormal : null;
                if (slide is Vector3 normal)
                {
                    slides.Add(normal);
                }

                var sample = new FrameSample(frame, mode.Position, mode.CellId, mode.IsOnGround, moved.LastRefusal, slide,
                    FloorObject(mode, moved), WallObject(moved, slide), moved, camera.Update(mode.Position, mode.CellId, mode.Heading));
                air = (air.Jumps + moved.Jumps, air.HeadHits + moved.HeadHits, air.Landings + moved.Landings, air.EdgeSlides + moved.EdgeSlides);
                if (before.IsOnGround && sample.IsOnGround && before.Position.Z - sample.Position.Z > PlayerMovementMode.StepUpHeight)
                {
                    drops.Add(new Drop(frame, before.Position.Z, before.CellId, sample.Position.Z, sample.CellId));
                }

                samples.Add(sample);
            }

            legs.Add(new LegResult(leg, first, frame, reached, refusals, slides) { Air = air });
            if (truncated)
            {
                break;
            }

            foreach (ScenePointer ray in (scene.Pointers ?? []).Where(p => p.AfterLeg == legs.Count))
            {
                pointers.Add(new PointerResult(ray, frame, pointer.Cast(ray.From, 0u, ray.Towards - ray.From)));
            }
        }

        return new WalkRecord(scene, samples, legs, streaming, drops, warnings, truncated)
        {
            Creatures = creatures.ConvertAll(c => c.Path()),
            Touches = touches,
            DoorChanges = doorChanges,
            Pointers = pointers,
            Drawn = drawing?.Lines ?? [],
        };

        // A landblock loaded: its doors (closed) and the creatures whose home is in it appear.
        void Populate(uint landblockId)
        {
            foreach (WorldDoor door in doors.Where(d => CellIds.LandblockOf(d.CellId) == landblockId))
            {
                window.AddMover(door.Id, door.Shape, door.Position, door.CellId, door.Orientation, MoverState.Door);
                doorsIn.Add(door.Id);
                doorStates.Remove(door.Id);
            }

            foreach (Creature creature in creatures.Where(c => c.Mode is null && engine.LandblockAt(new Vector3(c.Scene.Home, 0f)) == landblockId))
            {
                ResolveResult home = StartOnGround(new Vector3(creature.Scene.Home, 0f), engine);
                var walk = new PlayerMovementMode(engine, home.Position, home.CellId, 0f, MovementOptions.Player) { MoverId = creature.Id };
                window.AddMover(creature.Id, creatureShape, home.Position, home.CellId, Facing(walk.Heading), MoverState.Creature);
                creature.Appear(walk, frame);
            }
        }

        // A landblock unloaded: the window took its movers out of the engine; the creatures and doors in it leave the walk.
        void Depopulate(uint landblockId)
        {
            foreach (Creature creature in creatures.Where(c => c.Mode is PlayerMovementMode m && CellIds.LandblockOf(m.CellId) == landblockId))
            {
                creature.Disappear(frame, landblockId);
            }

            foreach (WorldDoor door in doors.Where(d => CellIds.LandblockOf(d.CellId) == landblockId))
            {
                doorsIn.Remove(door.Id);
                doorStates.Remove(door.Id);
            }
        }

        // The leg's door action, at its start: committed with its first frame, before the move.
        void DoorAction(SceneLeg leg)
        {
            foreach ((string? name, bool open) in new[] { (leg.Open, true), (leg.Close, false) })
            {
                if (name is not null && world.Doors[name].Id is uint id && doorsIn.Contains(id))
                {
                    if (open)
                    {
                        engine.Movers.Open(id);
                    }
                    else
                    {
                        engine.Movers.Close(id);
                    }
                }
            }
        }

        // After a commit: each registered door's state, recorded when it changed (or first seen).
        void RecordDoors()
        {
            foreach (WorldDoor door in doors)
            {
                if (!doorsIn.Contains(door.Id))
                {
                    continue;
                }

                DoorState state = engine.Movers.GetDoorState(door.Id);
                if (!doorStates.TryGetValue(door.Id, out DoorState last) || last != state)
                {
                    doorStates[door.Id] = state;
                    doorChanges.Add(new DoorChange(frame, door.Id, state));
                }
            }
        }

        // Each creature's move, after the player's; one whose answer ends inside a mover that has already moved this frame stays.
        void StepCreatures(PlayerMovementMode player)
        {
            foreach (Creature creature in creatures)
            {
                if (creature.Mode is not null)
                {
                    creature.Step(dt);
                }
            }

            for (int i = 0; i < creatures.Count; i++)
            {
                if (creatures[i].Mode is not PlayerMovementMode walk)
                {
                    continue;
                }

                bool inside = Overlap(walk.Position, MoverBody.Player, player.Position, playerBody);
                for (int j = 0; j < i && !inside; j++)
                {
                    inside = creatures[j].Mode is PlayerMovementMode other && Overlap(walk.Position, MoverBody.Player, other.Position, MoverBody.Player);
                }

                if (inside)
                {
                    creatures[i].HoldBack();
                }

                creatures[i].Record(frame);
                window.MoveMover(creatures[i].Id, walk.Position, walk.CellId, Facing(walk.Heading));
            }
        }
    }

    /// <summary>Whether two upright cylinders standing on <paramref name="a"/> and <paramref name="b"/> overlap: closer than their radii's sum across, and their heights overlapping.</summary>
    private static bool Overlap(Vector3 a, MoverBody bodyA, Vector3 b, MoverBody bodyB)
    {
        float reach = bodyA.Radius + bodyB.Radius;
        return Vector2.DistanceSquared(new Vector2(a.X, a.Y), new Vector2(b.X, b.Y)) < reach * reach
            && a.Z < b.Z + bodyB.Height && b.Z < a.Z + bodyA.Height;
    }

    /// <summary>A mover's orientation facing compass <paramref name="heading"/> (radians, 0 north, clockwise): its own +Y turned to the heading about Z.</summary>
    private static Quaternion Facing(float heading) => Quaternion.CreateFromAxisAngle(Vector3.UnitZ, -heading);

    /// <summary>
    /// The start on the terrain, as the engine has it: the ground's Z under the start, then the cell
    /// the engine puts a mover standing there in (a zero move; any outdoor id, 0 too, is recomputed).
    /// </summary>
    private static ResolveResult StartOnGround(Vector3 start, PhysicsEngine engine)
    {
        if (!engine.TryGetGround(start, 0u, out float groundZ, out _))
        {
            throw new InvalidOperationException($"the start ({start.X}, {start.Y}) is on land that did not load (landblock 0x{engine.LandblockAt(start):X8}).");
        }

        return engine.Resolve(start with { Z = groundZ }, 0u, Vector3.Zero, PlayerMovementMode.StepUpHeight);
    }

    /// <summary>The object whose floor the mover stands on after the frame, as the engine reported it, or 0.</summary>
    private static uint FloorObject(PlayerMovementMode mode, CharacterStep moved) =>
        mode.IsOnGround && moved.Met.Floor.Kind == SurfaceKind.ObjectFloor ? moved.Met.Floor.Id : 0;

    /// <summary>
    /// For a frame the engine answered Wall, OuterWall or Slid along a wall: the object whose wall, shell or
    /// cylinder it reported meeting (0 when it was a cell's wall).
    /// </summary>
    private static uint WallObject(CharacterStep moved, Vector3? slide)
    {
        bool wall = moved.LastRefusal is ResolveOutcome.Wall or ResolveOutcome.OuterWall || slide is Vector3 { Z: 0f };
        return wall && moved.Met.Wall.Kind is SurfaceKind.ObjectWall or SurfaceKind.BuildingShell or SurfaceKind.Cylinder ? moved.Met.Wall.Id : 0;
    }

    private static void Wait(GameWindow window)
    {
        if (!window.WaitForLoads(LoadTimeout))
        {
            throw new TimeoutException($"the landblock loader did not finish within {LoadTimeout.TotalSeconds} s.");
        }
    }
}
