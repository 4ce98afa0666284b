using System.Diagnostics.CodeAnalysis;
using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Point;

namespace AcDream.Core.Physics.Body;

/// <summary>
/// Plans a body's move: finds the landblock frame the mover is in, and slides the body among the walls
/// around it (<see cref="WallSet"/>, <see cref="BodySweep"/>). The path it returns is then walked leg by
/// leg by the point resolvers, which decide floors, cells and steps.
/// </summary>
internal sealed class BodyPlanner(WorldFrame frame)
{
    /// <summary>
    /// The path of a body of <paramref name="body"/> making the move <paramref name="q"/> (its feet, cell,
    /// horizontal delta and step); the path's points (in <paramref name="points"/>) are landblock-local in
    /// landblock (<paramref name="lbX"/>, <paramref name="lbY"/>). False when the mover's landblock is not
    /// loaded (no walls are known: the point move decides).
    /// </summary>
    [SkipLocalsInit] // the stack buffers are written before they are read
    public bool Plan(ref MoveQuery q, MoverBody body, scoped Span<Vector2> points, ref BodyPath path, out int lbX, out int lbY)
    {
        Place place;
        if (q.CellIndex == MoveQuery.Outdoors)
        {
            place = new Place(q.Here!, q.Here!.X, q.Here.Y, q.P0, -1); // located by the open-ground test
        }
        else if (!Locator.TryFind(frame, ref q.Lands, q.Position, q.CellId, out place))
        {
            (lbX, lbY) = (place.X, place.Y);
            return false;
        }

        (lbX, lbY) = (place.X, place.Y);
        (Vector2 local, LandblockEntry entry, int cellIndex) = (place.Local, place.Entry, place.CellIndex);
        if (cellIndex >= 0)
        {
            (q.Entry, q.P0, q.CellIndex) = (entry, local, cellIndex); // located once: the point move of the free path starts here
        }

        float skin = Skin(lbX, lbY, local, q.Delta.Length() + body.Radius);
        float reach = q.Delta.Length() + body.Radius + skin + PhysicsConstants.ContactTolerance; // every sweep of the slide stays this near the start
        Span<int> sources = stackalloc int[PhysicsConstants.BodySources];
        var move = BodyMove.Of(local, q.Delta, body.Radius + skin, 0.5f * skin, q.Z + q.StepUp, q.Z + body.Height);
        if (cellIndex >= 0 && entry.Cells[cellIndex].OpenFloor is OpenFloor open)
        {
            // On open floor: no wall reaches into the sweep's box and band, and no portal into the wall set's box, so the
            // slide below would touch nothing; its path is the move itself, as the slide writes it.
            float grow = move.Radius + PhysicsConstants.ContactTolerance;
            Vector2 end = local + q.Delta;
            if (open.IsOpen(Vector2.Min(local, end) - new Vector2(grow), Vector2.Max(local, end) + new Vector2(grow), move.ZLow, move.ZHigh, local - new Vector2(reach), local + new Vector2(reach))
                && !WallSet.TouchesMover(ref q.Lands, entry, in move, q.StepUp))
            {
                (points[0], points[1], path.Count) = (local, end, 2);
                q.Open = entry.Cells[cellIndex] is { Objects.Length: 0 } cell && !float.IsNaN(cell.FloorLevel);
                return true;
            }
        }

        var walls = new WallSet(ref q.Lands, entry, cellIndex, sources, new WallBox(local - new Vector2(reach), local + new Vector2(reach), move.ZLow, move.ZHigh), q.StepUp);
        BodySweep.Slide(in walls, in move, points, ref path);
        return true;
    }

    /// <summary>
    /// Whether an outdoor move of <paramref name="delta"/> (not zero) from the start of <paramref name="q"/> needs no plan:
    /// its landblock is not loaded (the point move holds or refuses it), or no wall lies in the box the body sweeps (the
    /// move's start and end grown by the radius, skin and contact tolerance), in its landblock or across a seam. Then the
    /// body meets no wall, and the point move is its answer; the mover located here is where that point move starts
    /// (<see cref="MoveQuery.CellIndex"/>). Indoor moves are always planned.
    /// </summary>
    public bool IsOpenGround(ref MoveQuery q, Vector2 delta, MoverBody body)
    {
        if (CellIds.IsIndoor(q.CellId))
        {
            return false;
        }

        frame.Locate(q.Position, q.CellId, out int lbX, out int lbY, out Vector2 local);
        if (q.Lands.Get(lbX, lbY) is not LandblockEntry entry)
        {
            return true;
        }

        (q.Here, q.P0, q.CellIndex) = (entry, local, MoveQuery.Outdoors); // located once

        // The box the body sweeps (its start and end grown by its radius, skin and the contact
        // tolerance): with no wall in it the body meets none on its way, so it does not slide, and its
        // move is the point's.
        float skin = Skin(lbX, lbY, local, delta.Length() + body.Radius);
        float grow = body.Radius + skin + PhysicsConstants.ContactTolerance;
        Vector2 min = Vector2.Min(local, local + delta) - new Vector2(grow), max = Vector2.Max(local, local + delta) + new Vector2(grow);
        bool open = !WallSet.AnyOutdoors(ref q.Lands, entry, min, max)
            && (q.Lands.Movers is null || !WallSet.TouchesMover(ref q.Lands, entry, BodyMove.Of(local, delta, body.Radius + skin, 0.5f * skin, q.Z + q.StepUp, q.Z + body.Height), q.StepUp));
        q.Open = open && !entry.FloorsBeyondWalls && !q.Lands.ReachInto(entry).Meets(min, max);
        return open;
    }

    /// <summary>
    /// How far a body of <paramref name="body"/> with its feet at <paramref name="position"/> (world) in
    /// <paramref name="cellId"/> reaches into the walls of its height band beyond what the float rounding
    /// may leave it (the sink, half its skin), metres: above zero it overlaps a wall, and
    /// <paramref name="outward"/> is the unit normal out of the deepest. Zero when its landblock is not loaded.
    /// </summary>
    [SkipLocalsInit] // the stack buffer is written before it is read
    public float Overlap(ref MoveQuery q, Vector3 position, uint cellId, MoverBody body, out Vector2 outward)
    {
        outward = default;
        if (!Locator.TryFind(frame, ref q.Lands, position, cellId, out Place place))
        {
            return 0f;
        }

        (int lbX, int lbY, Vector2 local, LandblockEntry entry, int cellIndex) = (place.X, place.Y, place.Local, place.Entry, place.CellIndex);
        float skin = Skin(lbX, lbY, local, body.Radius);
        float radius = body.Radius + skin;
        var hit = WallHit.None;
        Span<int> sources = stackalloc int[PhysicsConstants.BodySources];
        float reach = radius + PhysicsConstants.ContactTolerance;
        var still = new BodyMove(local, Vector2.Zero, radius, radius, 0.5f * skin, position.Z + q.StepUp, position.Z + body.Height);
        new WallSet(ref q.Lands, entry, cellIndex, sources, new WallBox(local - new Vector2(reach), local + new Vector2(reach), still.ZLow, still.ZHigh), q.StepUp)
            .Sweep(still, ref hit);
        outward = hit.Outward;
        float overlap = hit.Depth - (0.5f * skin);
        if (overlap > 0f)
        {
            q.Meet(hit.DeepSource.Kind, hit.DeepSource.Id);
        }

        return overlap;
    }

    /// <summary>
    /// Whether the body of <paramref name="q"/> that has stepped up from <paramref name="from"/> to
    /// <paramref name="position"/> (world; in <paramref name="cellId"/>) met a wall of its new height band on the
    /// way: the same closed-form sweep as <see cref="Plan"/>, along the step's horizontal move, in the band of the
    /// feet it stepped up to. Only a body moving into a wall (a lintel, a ceiling the step brought into the band) is
    /// stopped; one already overlapping a wall moves along or away from it freely, as its planned path did.
    /// <paramref name="normal"/>: that wall's normal, seen from above. False when its landblock is not loaded.
    /// </summary>
    [SkipLocalsInit] // the stack buffer is written before it is read
    public bool MetInNewBand(ref MoveQuery q, Vector3 from, Vector3 position, uint cellId, out Vector2 normal)
    {
        normal = default;
        MoverBody body = q.Options.Body!.Value;
        if (!Locator.TryFind(frame, ref q.Lands, position, cellId, out Place place))
        {
            return false;
        }

        (int lbX, int lbY, Vector2 local, LandblockEntry entry, int cellIndex) = (place.X, place.Y, place.Local, place.Entry, place.CellIndex);
        var move = new Vector2(position.X - from.X, position.Y - from.Y);
        Vector2 start = local - move;
        float length = move.Length();
        float skin = Skin(lbX, lbY, start, length + body.Radius);
        var step = BodyMove.Of(start, move, body.Radius + skin, 0.5f * skin, position.Z + q.StepUp, position.Z + body.Height);
        float reach = length + step.Radius + PhysicsConstants.ContactTolerance;
        Span<int> sources = stackalloc int[PhysicsConstants.BodySources];
        var hit = WallHit.None;
        new WallSet(ref q.Lands, entry, cellIndex, sources, new WallBox(start - new Vector2(reach), start + new Vector2(reach), step.ZLow, step.ZHigh), q.StepUp)
            .Sweep(step, ref hit);
        normal = hit.Normal;
        if (!((1f - hit.T) * length > PhysicsConstants.ContactTolerance))
        {
            return false; // not stopped short of where the step went: a rounding of a contact the path ended at
        }

        q.Meet(hit.Source.Kind, hit.Source.Id);
        return true;
    }

    /// <summary>
    /// How far a body of <paramref name="body"/> with its feet at <paramref name="position"/> (world; in
    /// <paramref name="cellId"/>) rises of <paramref name="dz"/> (&gt; 0) before its top meets the lowest surface over its
    /// disc (<see cref="Overhead"/>): a ceiling, a lintel, an upper floor, an object's underside, among the cells and
    /// objects around it (<see cref="WallSet"/>). Stopped, it keeps a gap of the body's skin under the surface, and
    /// <paramref name="normal"/> is the surface's (facing down); else zero. The whole rise when its landblock is not loaded.
    /// </summary>
    public float Rise(ref MoveQuery q, Vector3 position, uint cellId, MoverBody body, float dz, out Vector3 normal)
    {
        normal = default;
        if (!Locator.TryFind(frame, ref q.Lands, position, cellId, out Place place))
        {
            return dz;
        }

        float top = position.Z + body.Height;
        var reach = new Vector2(body.Radius + PhysicsConstants.ContactTolerance);
        if (place.CellIndex >= 0 && place.Entry.Cells[place.CellIndex] is { Objects.Length: 0, OpenFloor: OpenFloor open } cell
            && cell.FloorZMax <= top && open.IsOpen(place.Local - reach, place.Local + reach, top - PhysicsConstants.ContactTolerance, top + dz, place.Local - reach, place.Local + reach)
            && !WallSet.AnyMover(ref q.Lands, place.Entry, new WallBox(place.Local - reach, place.Local + reach, top - PhysicsConstants.ContactTolerance, top + dz)))
        {
            return dz; // on open floor: no wall or ceiling of the cell over the disc in the rise, no floor of it overhead, no portal to another cell's
        }

        var hit = new CeilingHit { Z = top + dz };
        Around(ref q, in place, new BodyRise(place.Local, body.Radius, top), (top - PhysicsConstants.ContactTolerance, top + dz), steep: false, ref hit);
        if (hit.Source.Kind == SurfaceKind.None)
        {
            return dz;
        }

        q.Meet(hit.Source.Kind, hit.Source.Id);
        normal = hit.Normal;
        MoveDrawing.Ceiling(position, hit.Z, hit.Normal);
        float skin = PhysicsConstants.BodySkin + (2f * Geometry.Spacing(MathF.Abs(hit.Z) + body.Height));
        return Math.Clamp(hit.Z - skin - top, 0f, dz);
    }

    /// <summary>
    /// Where a body of <paramref name="body"/> with its feet at <paramref name="position"/> (world; in <paramref name="cellId"/>)
    /// falling <paramref name="depth"/> metres meets a face too steep to stand on but not to land on (<see cref="Overhead.Steep"/>):
    /// the Z its feet rest at (the face's highest point over its disc), with the face's normal (up); NaN when it meets none.
    /// </summary>
    public float SteepUnder(ref MoveQuery q, Vector3 position, uint cellId, MoverBody body, float depth, out Vector3 normal)
    {
        normal = default;
        if (!Locator.TryFind(frame, ref q.Lands, position, cellId, out Place place)
            || (!place.Entry.HasSteep && !q.Lands.ReachInto(place.Entry).Meets(place.Local - new Vector2(body.Radius), place.Local + new Vector2(body.Radius))
                && !WallSet.AnyMover(ref q.Lands, place.Entry, new WallBox(place.Local - new Vector2(body.Radius), place.Local + new Vector2(body.Radius), position.Z - depth, position.Z))))
        {
            return float.NaN; // no face a fall may land on in its landblock, nor one reaching it across a seam, nor a mover's top
        }

        var hit = new CeilingHit { Z = position.Z - depth };
        Around(ref q, in place, new BodyRise(place.Local, body.Radius, position.Z), (position.Z - depth, position.Z), steep: true, ref hit);
        if (hit.Source.Kind == SurfaceKind.None)
        {
            return float.NaN;
        }

        normal = hit.Normal;
        return hit.Z;
    }

    /// <summary>
    /// The surfaces over (or, <paramref name="steep"/>, the steep faces under) the disc <paramref name="disc"/> in the height
    /// band <paramref name="band"/> (metres), among the cells and objects around <paramref name="place"/>, into <paramref name="hit"/>.
    /// </summary>
    [SkipLocalsInit] // the stack buffer is written before it is read
    private static void Around(ref MoveQuery q, in Place place, in BodyRise disc, (float Low, float High) band, bool steep, ref CeilingHit hit)
    {
        Span<int> sources = stackalloc int[PhysicsConstants.BodySources];
        var reach = new Vector2(disc.Radius + PhysicsConstants.ContactTolerance);
        var walls = new WallSet(ref q.Lands, place.Entry, place.CellIndex, sources, new WallBox(place.Local - reach, place.Local + reach, band.Low, band.High));
        if (steep)
        {
            walls.Steep(in disc, ref hit);
        }
        else
        {
            walls.Rise(in disc, ref hit);
        }
    }

    /// <summary>
    /// The gap the body keeps from walls beyond its radius: <see cref="PhysicsConstants.BodySkin"/>
    /// plus twice the float spacing of the coordinates it may reach, in the world frame and the
    /// landblock's, so rounding the answer to the world frame never puts the body into a wall.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private float Skin(int lbX, int lbY, Vector2 local, float reach)
    {
        Vector2 world = frame.Origin(lbX, lbY) + local;
        float largest = MathF.Max(MathF.Max(MathF.Abs(world.X), MathF.Abs(world.Y)), MathF.Max(MathF.Abs(local.X), MathF.Abs(local.Y))) + reach;
        return PhysicsConstants.BodySkin + (2f * Geometry.Spacing(largest));
    }
}
