using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.App.Scenes;

/// <summary>The mover after one frame.</summary>
/// <param name="Frame">Frame number; 0 is the start.</param>
/// <param name="Position">Feet, world metres.</param>
/// <param name="CellId">Cell id, <c>0xXXYYCCCC</c>.</param>
/// <param name="IsOnGround">On terrain or a floor.</param>
/// <param name="Refusal">The engine's outcome of this frame's last refused step; null when none was refused.</param>
/// <param name="Slide">The engine's surface normal of this frame's last step answered <see cref="ResolveOutcome.Slid"/> (a wall's, horizontal, or a slope's); null when none slid.</param>
/// <param name="FloorObjectId">The object whose floor the mover stands on, as the engine reported it (<see cref="MoveReport.Floor"/>); 0 for the terrain or a cell's floor, or in the air.</param>
/// <param name="WallObjectId">For a frame refused as Wall or OuterWall or slid along a wall: the object whose wall, shell or cylinder the engine reported it met (<see cref="MoveReport.Wall"/>); 0 otherwise or when it was a cell's wall.</param>
/// <param name="Moved">What the frame's movement did as the engine reported it (jumps, head hits, landings, edge slides among it).</param>
/// <param name="Camera">Where the chase camera (<see cref="Movement.ChaseCamera"/>) put its eye after the frame's move.</param>
internal readonly record struct FrameSample(int Frame, Vector3 Position, uint CellId, bool IsOnGround, ResolveOutcome? Refusal, Vector3? Slide = null, uint FloorObjectId = 0, uint WallObjectId = 0, AcDream.Core.Physics.CharacterStep Moved = default,
    Movement.CameraView Camera = default);

/// <summary>How a leg ended.</summary>
/// <param name="Leg">The leg.</param>
/// <param name="FirstFrame">First frame of the leg.</param>
/// <param name="LastFrame">Last frame of the leg (FirstFrame − 1 when it took none).</param>
/// <param name="Reached">Point leg: whether the point was reached; intent leg: whether it ran its full time.</param>
/// <param name="Refusals">Frames with a refused move during the leg, by the engine's outcome.</param>
/// <param name="Slides">The frames during the leg with a move the engine answered <see cref="ResolveOutcome.Slid"/>: the surface's normal the engine reported, one per such frame, in frame order.</param>
internal sealed record LegResult(SceneLeg Leg, int FirstFrame, int LastFrame, bool Reached, IReadOnlyDictionary<ResolveOutcome, int> Refusals, IReadOnlyList<Vector3> Slides)
{
    /// <summary>The leg's frames' jumps, head hits, landings and edge slides (<see cref="AcDream.Core.Physics.CharacterStep"/>).</summary>
    public (int Jumps, int HeadHits, int Landings, int EdgeSlides) Air { get; init; }
}

/// <summary>A landblock registered in or removed from the engine; <paramref name="Objects"/>: how many objects were registered with it.</summary>
internal readonly record struct StreamingEvent(int Frame, uint LandblockId, bool Loaded, int Objects = 0);

/// <summary>A frame where the mover went down more than the step height while staying on the ground.</summary>
internal readonly record struct Drop(int Frame, float FromZ, uint FromCellId, float ToZ, uint ToCellId);

/// <summary>An airborne span: the mover left the ground after <paramref name="TakeOffFrame"/> and landed at <paramref name="LandingFrame"/>.</summary>
/// <param name="TakeOffFrame">Last frame on the ground.</param>
/// <param name="LandingFrame">First frame on the ground again (−1: still airborne at the end).</param>
/// <param name="FromZ">Feet Z at take-off, metres.</param>
/// <param name="LandingZ">Feet Z at landing, metres.</param>
/// <param name="LandingCellId">The cell landed in.</param>
internal readonly record struct Fall(int TakeOffFrame, int LandingFrame, float FromZ, float LandingZ, uint LandingCellId)
{
    /// <summary>Frames spent in the air.</summary>
    public int AirborneFrames => LandingFrame - TakeOffFrame - 1;
}

/// <summary>Everything a scene run produced.</summary>
internal sealed record WalkRecord(
    Scene Scene,
    IReadOnlyList<FrameSample> Samples,
    IReadOnlyList<LegResult> Legs,
    IReadOnlyList<StreamingEvent> Streaming,
    IReadOnlyList<Drop> Drops,
    IReadOnlyList<string> Warnings,
    bool Truncated)
{
    /// <summary>The last sample: where the walk ended.</summary>
    public FrameSample Final => Samples[^1];

    /// <summary>The scene's creatures' walks, in the scene's order.</summary>
    public IReadOnlyList<CreaturePath> Creatures { get; init; } = [];

    /// <summary>What the player's moves saw, as the engine drew it (<see cref="FrameDrawing"/>), when the walk was drawn; empty otherwise.</summary>
    public IReadOnlyList<DrawnLine> Drawn { get; init; } = [];

    /// <summary>The movers the player's moves touched, frame by frame (each mover once a frame).</summary>
    public IReadOnlyList<MoverTouch> Touches { get; init; } = [];

    /// <summary>The scene's doors' states: each door's state when registered, then each change, in frame order.</summary>
    public IReadOnlyList<DoorChange> DoorChanges { get; init; } = [];

    /// <summary>The scene's pointer rays as cast, in the order cast.</summary>
    public IReadOnlyList<PointerResult> Pointers { get; init; } = [];

    /// <summary>
    /// The closest two creatures' centres came, seen from above, after any frame, of two whose heights overlap (one
    /// may stand on a plinth's edge above another): metres, the two ids and the frame; (∞, 0, 0, −1) with none.
    /// </summary>
    public (float Distance, uint A, uint B, int Frame) ClosestCreatures()
    {
        (float Distance, uint A, uint B, int Frame) closest = (float.PositiveInfinity, 0u, 0u, -1);
        var byFrame = Creatures.SelectMany(c => c.Samples.Select(s => (c.Id, s))).GroupBy(x => x.s.Frame);
        foreach (var frame in byFrame)
        {
            var at = frame.ToList();
            for (int i = 0; i < at.Count; i++)
            {
                for (int j = i + 1; j < at.Count; j++)
                {
                    Vector3 a = at[i].s.Position, b = at[j].s.Position;
                    float d = Vector2.Distance(new Vector2(a.X, a.Y), new Vector2(b.X, b.Y));
                    bool level = MathF.Abs(a.Z - b.Z) < MoverBody.Player.Height;
                    closest = level && d < closest.Distance ? (d, at[i].Id, at[j].Id, frame.Key) : closest;
                }
            }
        }

        return closest;
    }

    /// <summary>The closest a creature's centre came to the player's, seen from above, after any frame, their heights overlapping: metres, its id and the frame; (∞, 0, −1) with none.</summary>
    public (float Distance, uint Id, int Frame) ClosestToPlayer()
    {
        (float Distance, uint Id, int Frame) closest = (float.PositiveInfinity, 0u, -1);
        float height = Scene.Effects.Body?.Height ?? MoverBody.Player.Height;
        var player = Samples.ToDictionary(s => s.Frame, s => s.Position);
        foreach (CreaturePath creature in Creatures)
        {
            foreach (CreatureSample s in creature.Samples)
            {
                if (player.TryGetValue(s.Frame, out Vector3 p) && s.Position.Z < p.Z + height && p.Z < s.Position.Z + MoverBody.Player.Height)
                {
                    float d = Vector2.Distance(new Vector2(p.X, p.Y), new Vector2(s.Position.X, s.Position.Y));
                    closest = d < closest.Distance ? (d, creature.Id, s.Frame) : closest;
                }
            }
        }

        return closest;
    }

    /// <summary>Frames that ended off the ground.</summary>
    public int AirborneFrames => Samples.Count(s => !s.IsOnGround);

    /// <summary>The airborne spans, in order.</summary>
    public IReadOnlyList<Fall> Falls()
    {
        var falls = new List<Fall>();
        for (int i = 1; i < Samples.Count; i++)
        {
            if (Samples[i].IsOnGround || !Samples[i - 1].IsOnGround)
            {
                continue;
            }

            int land = i;
            while (land < Samples.Count && !Samples[land].IsOnGround)
            {
                land++;
            }

            FrameSample takeOff = Samples[i - 1];
            falls.Add(land < Samples.Count
                ? new Fall(takeOff.Frame, Samples[land].Frame, takeOff.Position.Z, Samples[land].Position.Z, Samples[land].CellId)
                : new Fall(takeOff.Frame, -1, takeOff.Position.Z, Samples[^1].Position.Z, Samples[^1].CellId));
            i = land;
        }

        return falls;
    }

    /// <summary>Frames over the whole walk whose move the engine refused with <paramref name="outcome"/>.</summary>
    public int RefusalCount(ResolveOutcome outcome) => Samples.Count(s => s.Refusal == outcome);

    /// <summary>The walk's jumps, head hits, landings and edge slides, over every frame.</summary>
    public (int Jumps, int HeadHits, int Landings, int EdgeSlides) Air =>
        (Samples.Sum(s => s.Moved.Jumps), Samples.Sum(s => s.Moved.HeadHits), Samples.Sum(s => s.Moved.Landings), Samples.Sum(s => s.Moved.EdgeSlides));

    /// <summary>Frames over the whole walk with a move the engine answered <see cref="ResolveOutcome.Slid"/>.</summary>
    public int SlideCount => Samples.Count(s => s.Slide is not null);

    /// <summary>The cells in the order visited, each with the frame it was entered (consecutive repeats collapsed).</summary>
    public IReadOnlyList<(int Frame, uint CellId)> CellVisits()
    {
        var visits = new List<(int, uint)>();
        foreach (FrameSample s in Samples)
        {
            if (visits.Count == 0 || visits[^1].Item2 != s.CellId)
            {
                visits.Add((s.Frame, s.CellId));
            }
        }

        return visits;
    }
}

/// <summary>A mover the player's move touched during one frame (the engine's answer, blocking or not).</summary>
/// <param name="Frame">The frame.</param>
/// <param name="MoverId">The mover's id.</param>
/// <param name="Stopped">Whether it is the wall the engine reported stopping or sliding the player that frame (<see cref="MoveReport.Wall"/>, <see cref="SurfaceKind.Mover"/>).</param>
internal readonly record struct MoverTouch(int Frame, uint MoverId, bool Stopped);

/// <summary>A scene's pointer ray (<see cref="ScenePointer"/>) and what it met, cast after frame <paramref name="Frame"/>.</summary>
internal readonly record struct PointerResult(ScenePointer Pointer, int Frame, Movement.PointerHit Hit);

/// <summary>A door's state from frame <paramref name="Frame"/> on, as committed at that frame's start (what its moves met).</summary>
internal readonly record struct DoorChange(int Frame, uint DoorId, DoorState State);

/// <summary>Where a creature was after one frame.</summary>
/// <param name="Frame">The frame.</param>
/// <param name="Position">Feet, world metres.</param>
/// <param name="CellId">Cell id, <c>0xXXYYCCCC</c>.</param>
internal readonly record struct CreatureSample(int Frame, Vector3 Position, uint CellId);

/// <summary>A creature's walk: one sample per frame it was in the world.</summary>
/// <param name="Id">Its mover id.</param>
/// <param name="Creature">What the scene says of it.</param>
/// <param name="Samples">Where it was after each frame it was in the world, in frame order.</param>
/// <param name="HeldBack">Frames its answer ended inside a mover that had already moved that frame, so it stayed.</param>
/// <param name="Removed">The frames it left the world with its landblock, and that landblock.</param>
internal sealed record CreaturePath(uint Id, SceneCreature Creature, IReadOnlyList<CreatureSample> Samples, int HeldBack, IReadOnlyList<(int Frame, uint LandblockId)> Removed);
