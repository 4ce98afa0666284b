using System.Numerics;
using System.Diagnostics.CodeAnalysis;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Point;

/// <summary>
/// One move's state, as one value through the resolvers: what the caller asked (position, cell,
/// horizontal delta, step height, effects), the landblocks the call reads (<see cref="Lands"/>, shared by
/// every move of one call), the move in its landblock's frame once located, and how many cell visits its
/// portal search has left. Passed by reference; nothing here allocates.
/// </summary>
internal ref struct MoveQuery
{
    /// <summary>The landblocks this call reads, each once (shared by every sub-move of the call).</summary>
    public ref Neighbourhood Lands;

    /// <summary>The mover's feet, world metres.</summary>
    public readonly Vector3 Position;

    /// <summary>The cell the caller says the mover is in.</summary>
    public readonly uint CellId;

    /// <summary>The horizontal move, metres.</summary>
    public readonly Vector2 Delta;

    /// <summary>Highest rise the move may climb, metres.</summary>
    public readonly float StepUp;

    /// <summary>The opt-in effects (the caller's, by reference: never copied).</summary>
    public readonly ref readonly MovementOptions Options;

    /// <summary>The landblock the move is resolved in (indoors: the cell's).</summary>
    public LandblockEntry Entry;

    /// <summary>Outdoors: the landblock under the mover, as read at the start of the call.</summary>
    public LandblockEntry? Here;

    /// <summary>Outdoors: where the mover stands, as located at the start of the call (a refusal keeps it there).</summary>
    public Standing Stand;

    /// <summary>The mover, landblock-local (a point that survives the round trip to the world frame).</summary>
    public Vector2 P0;

    /// <summary>The end of the move, landblock-local, likewise representable.</summary>
    public Vector2 P1;

    /// <summary>
    /// Once the body's planner has located the mover, so its point move does not locate it again: indoors its cell's
    /// index (with <see cref="Entry"/> and <see cref="P0"/>), outdoors <see cref="Outdoors"/> (with <see cref="Here"/> and
    /// <see cref="P0"/>); −1 until then.
    /// </summary>
    public int CellIndex;

    /// <summary>The <see cref="CellIndex"/> of an outdoor mover located by the body's planner.</summary>
    public const int Outdoors = -2;

    /// <summary>Cell visits the portal search may still make (<see cref="PhysicsConstants.MaxCellVisits"/> per call).</summary>
    public int CellVisitsLeft;

    /// <summary>
    /// Set with a refusal as a step too high that an object's floor caused (a stair's tread or ramp ahead, a
    /// plinth): such a rise may be the edge of a step, which a shorter move would take (see <see cref="PointMover.Step"/>).
    /// A rise of the terrain or a cell's floor is not.
    /// </summary>
    public bool ObjectStep;

    /// <summary>
    /// Set by the body's planner when nothing lies near the body's move: outdoors no cell's or object's wall and no object's
    /// floor past its walls in the box it sweeps (in its landblock and across seams), indoors an open floor in a cell whose
    /// floors are all at one height, with no object in it. Footing then has nothing to find beyond the ground under the centre.
    /// </summary>
    public bool Open;


    public MoveQuery(ref Neighbourhood lands, Vector3 position, uint cellId, Vector2 delta, float stepUp, ref readonly MovementOptions options)
    {
        Lands = ref lands;
        Position = position;
        CellId = cellId;
        Delta = delta;
        StepUp = stepUp;
        Options = ref options;
        Entry = null!;
        Here = null;
        Stand = default;
        P0 = default;
        P1 = default;
        CellIndex = -1;
        CellVisitsLeft = PhysicsConstants.MaxCellVisits;
    }

    /// <summary>The feet's Z, metres.</summary>
    public readonly float Z => Position.Z;

    /// <summary>A new move of the same call (its landblocks and what it met) with its own step and effects: a body's move through the air, or its fall.</summary>
    public readonly MoveQuery With(Vector3 position, uint cellId, Vector2 delta, float stepUp, ref readonly MovementOptions options)
    {
        var next = new MoveQuery(ref Lands, position, cellId, delta, stepUp, in options);
        return next;
    }

    /// <summary>A new move of the same call (its landblocks, step and effects) from <paramref name="position"/> in <paramref name="cellId"/> by <paramref name="delta"/>.</summary>
    public readonly MoveQuery Next(Vector3 position, uint cellId, Vector2 delta)
    {
        var next = new MoveQuery(ref Lands, position, cellId, delta, StepUp, in Options);
        return next;
    }

    /// <summary>Records the wall, shell or cylinder that stops or slides this move (kind and id; the answer gives the normal), when the caller asked.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Meet(SurfaceKind kind, uint id)
    {
        if (Lands.Reporting)
        {
            (Lands.MetKind, Lands.MetId) = (kind, id);
        }
    }

    /// <summary>Records the wall <paramref name="hit"/> met among objects (<see cref="Meet(SurfaceKind, uint)"/>).</summary>
    public readonly void Meet(in ObjectHit hit)
    {
        if (hit.Wall is ObjectSurface o)
        {
            Meet(hit.Cylinder ? SurfaceKind.Cylinder : o.IsBuilding ? SurfaceKind.BuildingShell : SurfaceKind.ObjectWall, o.ObjectId);
        }
    }

    /// <summary>Checks the arguments of a Resolve call; the exceptions name the spec's parameters.</summary>
    /// <remarks>
    /// The checks inline into Resolve; the messages are built out of line (<see cref="ThrowInvalid"/>),
    /// so Resolve's frame carries no string builders to zero on every call.
    /// </remarks>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Validate(Vector3 pos, uint cellId, Vector3 delta, float stepUp)
    {
        if (!(Geometry.IsFinite(pos) && Geometry.IsFinite(delta) && float.IsFinite(stepUp) && stepUp >= 0f && CellIds.IsCellOfTheWorld(cellId)))
        {
            ThrowInvalid(pos, cellId, delta, stepUp, Spec);
        }
    }

    /// <summary>The check of the four arguments (<c>Validate(Vector3, uint, Vector3, float)</c>) on a <see cref="MoveRequest"/>: the exception names the argument <c>request</c> and the field.</summary>
    public static void Validate(in MoveRequest request)
    {
        if (!(Geometry.IsFinite(request.Position) && Geometry.IsFinite(request.Delta) && float.IsFinite(request.StepUpHeight)
              && request.StepUpHeight >= 0f && CellIds.IsCellOfTheWorld(request.CellId)))
        {
            ThrowInvalid(request.Position, request.CellId, request.Delta, request.StepUpHeight, Request);
        }
    }

    /// <summary>How the spec's call names its arguments: position, cell, delta, step; its <c>paramName</c> is each one's.</summary>
    private static readonly string[] Spec = ["currentPos", "currentCellId", "delta", "stepUpHeight"];

    /// <summary>How a request's fields are named; its <c>paramName</c> is <c>request</c>.</summary>
    private static readonly string[] Request = ["request.Position", "request.CellId", "request.Delta", "request.StepUpHeight"];

    /// <summary>The exception for the first argument <c>Validate</c> finds wrong.</summary>
    [DoesNotReturn]
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static void ThrowInvalid(Vector3 pos, uint cellId, Vector3 delta, float stepUp, string[] names)
    {
        bool request = ReferenceEquals(names, Request);
        string Param(int i) => request ? "request" : names[i];
        if (!Geometry.IsFinite(pos))
        {
            throw new ArgumentException($"{names[0]} {pos} must be finite (cell 0x{cellId:X8}).", Param(0));
        }

        if (!Geometry.IsFinite(delta))
        {
            throw new ArgumentException($"{names[2]} {delta} must be finite (cell 0x{cellId:X8}).", Param(2));
        }

        if (!float.IsFinite(stepUp) || stepUp < 0f)
        {
            throw new ArgumentOutOfRangeException(Param(3), stepUp, $"{names[3]} must be a finite height ≥ 0 m (cell 0x{cellId:X8}).");
        }

        uint low = cellId & 0xFFFF;
        if ((low > PhysicsConstants.CellsPerSide * PhysicsConstants.CellsPerSide && low < CellIds.FirstIndoor) || low > CellIds.LastIndoor)
        {
            throw new ArgumentException($"{names[1]} 0x{cellId:X8} is not a cell: outdoor cells are 0x0001..0x0040, indoor 0x0100..0xFFFD.", Param(1));
        }

        throw new ArgumentException(
            $"{names[1]} 0x{cellId:X8} names a landblock off the world: X and Y must be within 0x00..0x{PhysicsConstants.MaxLandblockIndex:X2}.", Param(1));
    }

}

/// <summary>How a move's answer is formed once its ground is known; shared by both resolvers.</summary>
internal static class Answers
{
    /// <summary>
    /// A move made of parts (sub-steps, legs): after the accepted <paramref name="last"/>, the next part's
    /// answer; when that part is refused, the last accepted position with the refusal's outcome and normal.
    /// </summary>
    public static ResolveResult Continue(ResolveResult last, ResolveResult next) =>
        next.IsRefused ? last with { Outcome = next.Outcome, SurfaceNormal = next.SurfaceNormal } : next;

    /// <summary>
    /// The result of arriving over ground at <paramref name="ground"/>: on it, or, with step down on
    /// and the ground farther below the feet than the step-down height (and the ground tolerance),
    /// airborne at the feet's Z.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static ResolveResult Land(Vector3 ground, float z, uint cellId, in MovementOptions options) =>
        options.StepDownHeight is float down && z - ground.Z > MathF.Max(down, PhysicsConstants.GroundTolerance)
            ? new ResolveResult(ground with { Z = z }, cellId, false)
            : new ResolveResult(ground, cellId, true);

    /// <summary>
    /// A refused move <paramref name="q"/>: the mover stays where <paramref name="stay"/> says (landblock-local, its
    /// landblock and cell; its ground Z is not read), at the feet's Z. Against <paramref name="ground"/> (the terrain, or its cell's floor nearest its
    /// feet, under it; null when there is none): feet within <see cref="PhysicsConstants.GroundTolerance"/>
    /// of it keep their Z and stand on it (the spec's "keep currentPos"); feet deeper below it (sunk), or
    /// above it by no more than the step-down height, are put on it; feet higher keep their Z and are
    /// airborne, so the caller's gravity acts.
    /// </summary>
    public static ResolveResult Refuse(in WorldFrame frame, ref MoveQuery q, in Standing stay, float? ground, ResolveOutcome why, Vector3 normal = default) =>
        RefuseAt(in frame, stay.X, stay.Y, stay.Local, q.Z, ground, stay.CellId, in q.Options, why, normal);

    /// <summary>
    /// <see cref="Refuse"/> on plain values. Its ten parameters are measured: the same body reading the query and the
    /// place by reference (or one value of the outcome and normal) made the refusal-heavy rows (walkable slope, the
    /// player's options outdoors) 10–15 % slower.
    /// </summary>
    private static ResolveResult RefuseAt(in WorldFrame frame, int lbX, int lbY, Vector2 local, float z, float? ground, uint cellId, in MovementOptions options, ResolveOutcome why, Vector3 normal)
    {
        var at = frame.ToWorld(lbX, lbY, local, z);
        bool onGround = false;
        if (ground is float g)
        {
            float above = z - g;
            if (MathF.Abs(above) <= PhysicsConstants.GroundTolerance)
            {
                onGround = true;
            }
            else if (above < 0f || (options.StepDownHeight is float down && above <= down))
            {
                (at.Z, onGround) = (g, true);
            }
        }

        return new ResolveResult(at, cellId, onGround) { Outcome = why, SurfaceNormal = normal };
    }
}

/// <summary>An outdoor mover's place: landblock (X, Y), its landblock-local point, the terrain's Z there and its outdoor cell id.</summary>
internal readonly record struct Standing(int X, int Y, Vector2 Local, float GroundZ, uint CellId);
