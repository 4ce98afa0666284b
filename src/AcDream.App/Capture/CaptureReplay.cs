using AcDream.App.Scenes;
using AcDream.App.World;
using AcDream.Core.Physics;

namespace AcDream.App.Capture;

/// <summary>
/// Replays a capture: rebuilds the scene's static world as the scene runner does (the scene's <see cref="HoltburgWorld"/>,
/// its landblocks built by a <see cref="GameWindow"/> in an engine of the capture's frame), applies the recorded calls in
/// order to that fresh engine, and compares each answer with the recorded one, bit for bit (<see cref="CaptureBits"/>). It stops at the first call whose answer differs, or that throws where the recorded call
/// returned.
/// </summary>
internal static class CaptureReplay
{
    /// <summary>What a call that has no answer gives: it returned.</summary>
    public const string Returned = "(returned)";

    /// <summary>Replays <paramref name="calls"/> (line 2 on of a capture) in the world <paramref name="header"/> names.</summary>
    /// <returns>The first call whose answer differs, or null when every answer is the same.</returns>
    /// <exception cref="CaptureFormatException">The header's scene cannot be read, its frame is global (the scene runner's engines are centred), or a mover's shape names no door of the scene's world: nothing is replayed.</exception>
    public static ReplayDifference? Run(CaptureHeader header, IReadOnlyList<CaptureCall> calls)
    {
        Scene scene;
        try
        {
            scene = header.Scene == CaptureHeader.EmbeddedDefault ? SceneReader.ReadDefault() : SceneReader.ReadFile(header.Scene);
        }
        catch (SceneFormatException e)
        {
            throw new CaptureFormatException(1, "scene", $"the scene cannot be read: {e.Message}");
        }

        uint centre = header.Centre ?? throw new CaptureFormatException(1, "frame", "the replay builds the world as the scene runner does, in an engine centred on a landblock; this capture's frame is global.");
        HoltburgWorld world = scene.CreateWorld();
        var shapes = new MoverShape[calls.Count];
        for (int i = 0; i < calls.Count; i++)
        {
            if (calls[i].Shape is CaptureShape shape)
            {
                shapes[i] = shape.Cylinder is MoverBody body ? MoverShape.Cylinder(body.Radius, body.Height)
                    : world.Doors.TryGetValue(shape.Door!, out WorldDoor? door) ? door.Shape
                    : throw new CaptureFormatException(i + 2, "shape.door", $"\"{shape.Door}\" is not a door of the scene's world ({string.Join(", ", world.Doors.Keys)}).");
            }
        }

        using var window = new GameWindow(world, world.HeightTable, centre);
        for (int i = 0; i < calls.Count; i++)
        {
            CaptureCall call = calls[i];
            CaptureAnswer? replayed;
            try
            {
                replayed = Apply(window, world, call, shapes[i]);
            }
            catch (Exception e) when (e is ArgumentException or InvalidOperationException)
            {
                return new ReplayDifference(i + 2, call, Text(call.Kind, call.Answer), $"threw {e.GetType().Name}: {e.Message}");
            }

            if (!CaptureBits.Same(call.Kind, call.Answer, replayed))
            {
                return new ReplayDifference(i + 2, call, Text(call.Kind, call.Answer), Text(call.Kind, replayed));
            }
        }

        return null;
    }

    /// <summary>The text of an answer, as a capture's line holds it: floats as their bits, so equal texts are equal bits.</summary>
    public static string Text(CaptureKind kind, CaptureAnswer? answer) => answer is null ? Returned : CaptureJson.Text(w => CaptureJson.WriteAnswer(w, kind, answer));

    private static CaptureAnswer? Apply(GameWindow window, HoltburgWorld world, CaptureCall call, MoverShape? shape)
    {
        PhysicsEngine engine = window.Physics;
        MoverRegistry movers = engine.Movers;
        CaptureAnswer? answer = null;
        switch (call.Kind)
        {
            case CaptureKind.AddLandblock:
                if (!window.ApplyLoadedTerrainLocked(call.Id, world.Load(call.Id), out string? error))
                {
                    throw new InvalidOperationException($"landblock 0x{call.Id:X8} could not be built: {error}");
                }

                break;
            case CaptureKind.RemoveLandblock:
                engine.RemoveLandblock(call.Id);
                break;
            case CaptureKind.AddMover:
                movers.Add(call.Id, shape!, call.Position, call.CellId, call.Orientation, call.State);
                break;
            case CaptureKind.MoveMover:
                movers.Move(call.Id, call.Position, call.CellId, call.Orientation);
                break;
            case CaptureKind.SetState:
                movers.SetState(call.Id, call.State);
                break;
            case CaptureKind.Open:
                movers.Open(call.Id);
                break;
            case CaptureKind.Close:
                movers.Close(call.Id);
                break;
            case CaptureKind.RemoveMover:
                answer = new CaptureAnswer(Removed: movers.Remove(call.Id));
                break;
            case CaptureKind.RemoveMovers:
                answer = new CaptureAnswer(Count: movers.RemoveLandblock(call.Id));
                break;
            case CaptureKind.Commit:
                movers.Commit();
                answer = new CaptureAnswer(Commit: movers.CommitNumber);
                break;
            case CaptureKind.Resolve:
                var touched = new uint[call.Span];
                MoveRequest request = call.Move;
                MoveResult result = engine.Resolve(in request, touched);
                answer = new CaptureAnswer(Move: result, Touched: touched[..Math.Min(result.TouchedCount, touched.Length)]);
                break;
            case CaptureKind.Cast:
                CastRequest cast = call.Cast;
                answer = new CaptureAnswer(Hit: engine.Cast(in cast));
                break;
        }

        return answer;
    }
}

/// <summary>The first call of a replay whose answer differs from the recorded one.</summary>
/// <param name="Line">Its line in the capture (1 is the header).</param>
/// <param name="Call">The call, with its inputs.</param>
/// <param name="Recorded">The recorded answer's text.</param>
/// <param name="Replayed">The replayed answer's text (or what the call threw).</param>
internal sealed record ReplayDifference(int Line, CaptureCall Call, string Recorded, string Replayed);
