using System.Numerics;
using AcDream.Core.Physics.Drawing;
using AcDream.Core.Physics.Movers;
using AcDream.Core.Physics.Point;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics;

/// <summary>Debug drawing: the surfaces near a point, and what a move saw, into a sink the caller implements.</summary>
public sealed partial class PhysicsEngine
{
    /// <summary>How long the normals drawn for contacts and ceilings are, metres (and a held edge's segment).</summary>
    public const float DrawNormalLength = 0.25f;

    /// <summary>
    /// Draws into <paramref name="sink"/> the registered surfaces near <paramref name="position"/>: terrain triangles, cells'
    /// floor triangles, wall edges and portal outlines, objects' floor triangles, wall edges and cylinders, and the committed
    /// movers' walls (see <see cref="DrawKind"/> for each kind's id).
    /// </summary>
    /// <remarks>
    /// <para>
    /// Near: every surface whose bounds, seen from above, meet the square of half-side <paramref name="radius"/> around the
    /// position (a terrain triangle's 24 m cell, a floor triangle, a wall polygon, a portal, a mover's wall), in the
    /// position's landblock and its eight neighbours; heights are not culled. Each point drawn is the surface's own: a wall
    /// polygon's vertex, a floor triangle's corner at the triangle's Z there, a portal polygon's vertex, a cylinder's point
    /// on its radius at its bottom or top, a terrain cell's corner at its height; in world metres of this engine's frame
    /// (see <see cref="IDebugSink"/> for the rounding).
    /// </para>
    /// <para>
    /// Reads the landblocks and the committed movers as a <c>Resolve</c> does (safe beside other calls); allocates nothing
    /// (a struct sink is called without boxing). Calls with a landblock not registered draw nothing of it.
    /// </para>
    /// </remarks>
    /// <typeparam name="TSink">The sink's type: a struct is called directly, a class through its interface.</typeparam>
    /// <param name="position">The centre, world metres.</param>
    /// <param name="cellId">The cell the position is in (<c>0xXXYYCCCC</c>; an outdoor number is recomputed from the position), as for <c>Resolve</c>.</param>
    /// <param name="radius">Half the square's side, metres, 0 ≤ radius ≤ <see cref="PhysicsConstants.LandblockSize"/>.</param>
    /// <param name="sink">Where to draw.</param>
    /// <exception cref="ArgumentNullException"><paramref name="sink"/> is null.</exception>
    /// <exception cref="ArgumentException">The position is not finite, or the cell is not a cell of the world.</exception>
    /// <exception cref="ArgumentOutOfRangeException">The radius is NaN, negative or more than a landblock.</exception>
    public void DrawNear<TSink>(Vector3 position, uint cellId, float radius, ref TSink sink)
        where TSink : IDebugSink
    {
        if (sink is null)
        {
            throw new ArgumentNullException(nameof(sink), $"DrawNear at {position} (cell 0x{cellId:X8}): the sink is null.");
        }

        if (!Geometry.IsFinite(position))
        {
            throw new ArgumentException($"position {position} (cell 0x{cellId:X8}) must be finite.", nameof(position));
        }

        if (!CellIds.IsCellOfTheWorld(cellId))
        {
            throw new ArgumentException($"cellId 0x{cellId:X8} is not a cell of the world (0x0000..0x0040 outdoors, 0x0100..0xFFFD indoors, landblock X and Y below 0xFF).", nameof(cellId));
        }

        if (!(radius >= 0f && radius <= PhysicsConstants.LandblockSize))
        {
            throw new ArgumentOutOfRangeException(nameof(radius), radius, $"DrawNear at {position} (cell 0x{cellId:X8}): the radius must be 0..{PhysicsConstants.LandblockSize} m.");
        }

        _frame.Locate(position, cellId, out int x, out int y, out Vector2 local);
        var half = new Vector2(radius);
        for (int dx = -1; dx <= 1; dx++)
        {
            for (int dy = -1; dy <= 1; dy++)
            {
                if (_registry.Get(x + dx, y + dy) is LandblockEntry entry)
                {
                    var shift = new Vector2(dx * PhysicsConstants.LandblockSize, dy * PhysicsConstants.LandblockSize);
                    NearDrawing.Landblock(in _frame, entry, new NearDrawing.Box(local - half - shift, local + half - shift), ref sink);
                }
            }
        }

        MoverFrame? movers = _movers.Hold();
        try
        {
            if (movers is not null)
            {
                NearDrawing.Movers(in _frame, movers, x, y, new NearDrawing.Box(local - half, local + half), ref sink);
            }
        }
        finally
        {
            MoverRegistry.Release(movers);
        }
    }

    /// <summary>
    /// <see cref="Resolve(in MoveRequest, Span{uint})"/> (with no touches asked), drawing into <paramref name="sink"/> what
    /// the move saw: each sub-step of its sweep (<see cref="DrawKind.SubStep"/>, the last ending at the answer), the walls
    /// it met with their normals (<see cref="DrawKind.Contact"/>), the edge it was held at, the ceiling its rise met, and what
    /// the answer stands on: the floor under its centre or, when footing holds it there, the floor under its footprint.
    /// </summary>
    /// <remarks>
    /// The answer is bit for bit that of <c>Resolve</c> with the same request: the drawing is read from the move, never into
    /// it. A sub-step of a move not swept is the move itself. The contact of a wall, slide or refusal answer is drawn at the
    /// answer (a body's side toward the wall, half its height up; a point's feet) along <see cref="ResolveResult.SurfaceNormal"/>;
    /// a body's path turned or stopped by a wall also draws the contact where it met it. Allocates nothing beyond what
    /// the sink does. While it runs, the move's hooks on this thread call the sink; other threads' moves draw nothing.
    /// </remarks>
    /// <param name="request">The move, as for <c>Resolve</c>.</param>
    /// <param name="sink">Where to draw.</param>
    /// <param name="touched">As <c>Resolve</c>'s: where to write the movers touched (empty: none looked for).</param>
    /// <returns>The answer of <c>Resolve(in request, touched)</c>.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="sink"/> is null.</exception>
    /// <exception cref="ArgumentException">As <c>Resolve</c>.</exception>
    public MoveResult DrawMove(in MoveRequest request, IDebugSink sink, Span<uint> touched = default)
    {
        ArgumentNullException.ThrowIfNull(sink);
        MoveQuery.Validate(in request);
        MoveResult moved;
        Vector3 last;
        MoveDrawing.Begin(sink, request.MoverId, request.Position);
        try
        {
            moved = Resolve(in request, touched);
        }
        finally
        {
            MoveDrawing.End(out last);
        }

        ResolveResult answer = moved.Answer;
        if (last != answer.Position)
        {
            sink.Line(last, answer.Position, DrawKind.SubStep, request.MoverId); // the settling after the last sub-step: to the answer
        }

        DrawAnswer(in request, in answer, sink);
        return moved;
    }

    /// <summary>The answer's contact, and the floor and support it stands on.</summary>
    private void DrawAnswer(in MoveRequest request, in ResolveResult answer, IDebugSink sink)
    {
        Vector3 normal = answer.SurfaceNormal;
        bool walled = answer.Outcome is ResolveOutcome.Wall or ResolveOutcome.OuterWall or ResolveOutcome.StepTooHigh or ResolveOutcome.SlopeTooSteep
            || (answer.Outcome == ResolveOutcome.Slid && normal.Z == 0f);
        if (walled && normal != Vector3.Zero)
        {
            Vector3 at = answer.Position;
            if (request.Options.Body is MoverBody body)
            {
                var across = Vector3.Normalize(new Vector3(normal.X, normal.Y, 0f));
                at = across.X is float.NaN ? at : at - (across * body.Radius) + new Vector3(0f, 0f, 0.5f * body.Height);
            }

            sink.Line(at, at + (normal * DrawNormalLength), DrawKind.Contact, request.MoverId);
        }

        MovementOptions options = request.Options;
        var lands = new Neighbourhood(_registry);
        FootingDrawing.Draw(in _frame, ref lands, in answer, in options, ref sink);
    }
}
