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
internal static class SceneRunner
{
    /// <summary>Simulation rate: 30 frames per second.</summary>
    public const int FramesPerSecond = 30;

    /// <summary>A point leg ends when the mover is this close to its point, metres.</summary>
    public const float ArrivalDistance = 0.01f;

    /// <summary>Longest wait for one frame's landblock loads before the run gives up: 30 s.</summary>
    private static readonly TimeSpan LoadTimeout = TimeSpan.FromSeconds(30);

    /// <summary>Runs <paramref name="scene"/> in its own world (<see cref="Scene.CreateWorld"/>).</summary>
    public static WalkRecord Run(Scene scene, int? maxFrames = null) => Run(scene, scene.CreateWorld(), maxFrames);

    /// <summary>Runs <paramref name="scene"/>; stops after <paramref name="maxFrames"/> frames if given.</summary>
    /// <exception cref="ArgumentException"><paramref name="world"/> is not the scene's world with its objects.</exception>
    public static WalkRecord Run(Scene scene, HoltburgWorld world, int? maxFrames = null)
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
        int frame = 0;

        using var window = new GameWindow(world, world.HeightTable, world.Center, warnings.Add);
        window.LandblockLoaded += id => streaming.Add(new StreamingEvent(frame, id, true, window.ObjectCounts.GetValueOrDefault(id)));
        window.LandblockUnloaded += id => streaming.Add(new StreamingEvent(frame, id, false));
        PhysicsEngine engine = window.Physics;

        var startXY = new Vector3(scene.Start, 0f);
        window.UpdateStreaming(startXY);
        Wait(window);
        window.UpdateStreaming(startXY);
        ResolveResult start = StartOnGround(startXY, engine);

        var mode = new PlayerMovementMode(engine, start.Position, start.CellId, scene.StartHeadingDegrees * (MathF.PI / 180f), scene.Effects);
        samples.Add(new FrameSample(0, start.Position, start.CellId, start.IsOnGround, null));

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
                FrameSample before = samples[^1];
                MovementFrame moved = mode.Update(intent, dt);
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
                    FloorObject(mode, moved), WallObject(moved, slide), moved);
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
        }

        return new WalkRecord(scene, samples, legs, streaming, drops, warnings, truncated);
    }

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
    private static uint FloorObject(PlayerMovementMode mode, MovementFrame moved) =>
        mode.IsOnGround && moved.Met.Floor.Kind == SurfaceKind.ObjectFloor ? moved.Met.Floor.Id : 0;

    /// <summary>
    /// For a frame the engine answered Wall, OuterWall or Slid along a wall: the object whose wall, shell or
    /// cylinder it reported meeting (0 when it was a cell's wall).
    /// </summary>
    private static uint WallObject(MovementFrame moved, Vector3? slide)
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
