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

    private static readonly TimeSpan LoadTimeout = TimeSpan.FromSeconds(30);

    /// <summary>Runs <paramref name="scene"/>; stops after <paramref name="maxFrames"/> frames if given.</summary>
    public static WalkRecord Run(Scene scene, HoltburgWorld world, int? maxFrames = null)
    {
        const float dt = 1f / FramesPerSecond;
        var warnings = new List<string>();
        var streaming = new List<StreamingEvent>();
        var samples = new List<FrameSample>();
        var legs = new List<LegResult>();
        var drops = new List<Drop>();
        int frame = 0;

        using var window = new GameWindow(world, world.HeightTable, HoltburgWorld.Holtburg, warnings.Add);
        window.LandblockLoaded += id => streaming.Add(new StreamingEvent(frame, id, true));
        window.LandblockUnloaded += id => streaming.Add(new StreamingEvent(frame, id, false));
        PhysicsEngine engine = window.Physics;

        Vector3 start = StartOnGround(scene.Start, window, world, out uint startCell);
        window.UpdateStreaming(start);
        Wait(window);
        window.UpdateStreaming(start);

        var mode = new PlayerMovementMode(engine, start, startCell, scene.StartHeadingDegrees * (MathF.PI / 180f), scene.Effects);
        samples.Add(new FrameSample(0, start, startCell, true, null));
        List<CellSurface> indoor = world.Cells.Select(c => new CellSurface(c.CellId, c.EnvCell, c.CellStruct)).ToList();
        Vector3 indoorOrigin = engine.GetLandblockOrigin(HoltburgWorld.Holtburg);

        bool truncated = false;
        foreach (SceneLeg leg in scene.Legs)
        {
            int first = frame + 1;
            int limit = (int)MathF.Round(leg.Seconds * FramesPerSecond);
            var refusals = new Dictionary<RefusalReason, int>();
            bool reached = false;
            for (int n = 0; ; n++)
            {
                MovementIntent intent;
                if (leg.To is Vector2 to)
                {
                    Vector2 away = to - new Vector2(mode.Position.X, mode.Position.Y);
                    float distance = away.Length();
                    if (distance <= ArrivalDistance)
                    {
                        reached = true;
                        break;
                    }

                    if (n >= limit)
                    {
                        break;
                    }

                    mode.Heading = MathF.Atan2(away.X, away.Y) + (leg.Backward ? MathF.PI : 0f);
                    float stepLength = (leg.Run ? PlayerMovementMode.RunSpeed : PlayerMovementMode.WalkSpeed) * dt;
                    float speed = MathF.Min(1f, distance / stepLength);
                    intent = new MovementIntent(leg.Backward ? -speed : speed, 0f, 0f, leg.Run);
                }
                else
                {
                    if (n >= limit)
                    {
                        reached = true;
                        break;
                    }

                    intent = new MovementIntent(leg.Forward, leg.Strafe, leg.Turn, leg.Run);
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
                RefusalReason? refusal = null;
                if (moved.RejectedSteps > 0)
                {
                    refusal = Classify(moved, window, indoor, indoorOrigin);
                    refusals[refusal.Value] = refusals.GetValueOrDefault(refusal.Value) + 1;
                }

                var sample = new FrameSample(frame, mode.Position, mode.CellId, mode.IsOnGround, refusal);
                if (before.IsOnGround && sample.IsOnGround && before.Position.Z - sample.Position.Z > PlayerMovementMode.StepUpHeight)
                {
                    drops.Add(new Drop(frame, before.Position.Z, before.CellId, sample.Position.Z, sample.CellId));
                }

                samples.Add(sample);
            }

            legs.Add(new LegResult(leg, first, frame, reached, refusals));
            if (truncated)
            {
                break;
            }
        }

        return new WalkRecord(scene, samples, legs, streaming, drops, warnings, truncated);
    }

    /// <summary>The start on the terrain, and its outdoor cell id.</summary>
    private static Vector3 StartOnGround(Vector2 start, GameWindow window, HoltburgWorld world, out uint cellId)
    {
        uint landblock = window.LandblockAt(new Vector3(start, 0f));
        Vector3 origin = window.Physics.GetLandblockOrigin(landblock);
        TerrainSurface terrain = world.Terrain(landblock);
        float x = start.X - origin.X, y = start.Y - origin.Y;
        cellId = (landblock & 0xFFFF0000u) | terrain.ComputeOutdoorCellId(x, y);
        return new Vector3(start, terrain.SampleZ(x, y));
    }

    private static void Wait(GameWindow window)
    {
        if (!window.WaitForLoads(LoadTimeout))
        {
            throw new TimeoutException($"the landblock loader did not finish within {LoadTimeout.TotalSeconds} s.");
        }
    }

    /// <summary>
    /// Why a move was refused. The engine returns only the unchanged position, so the host looks at
    /// what is ahead: unloaded land; outdoors, the terrain rising too fast (the only outdoor refusal);
    /// indoors, a floor ahead more than the step height up (but less than a storey), else a wall.
    /// </summary>
    private static RefusalReason Classify(MovementFrame moved, GameWindow window, List<CellSurface> indoor, Vector3 indoorOrigin)
    {
        Vector3 from = moved.RejectedFrom, target = from + moved.RejectedDelta;
        if (!window.Physics.ContainsLandblock(window.LandblockAt(from)) || !window.Physics.ContainsLandblock(window.LandblockAt(target)))
        {
            return RefusalReason.UnloadedLand;
        }

        if ((moved.RejectedCellId & 0xFFFF) < 0x0100)
        {
            return RefusalReason.StepTooHigh;
        }

        Vector3 local = target - indoorOrigin;
        foreach (CellSurface cell in indoor)
        {
            if ((cell.CellId & 0xFFFF0000u) == (moved.RejectedCellId & 0xFFFF0000u)
                && cell.SampleFloorZ(local.X, local.Y, from.Z) is float z
                && z - from.Z > PlayerMovementMode.StepUpHeight && z - from.Z < 2.5f)
            {
                return RefusalReason.StepTooHigh;
            }
        }

        return RefusalReason.Wall;
    }
}
