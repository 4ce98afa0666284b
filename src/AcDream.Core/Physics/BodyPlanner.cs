using System.Diagnostics.CodeAnalysis;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics;

/// <summary>
/// Plans a body's move: finds the landblock frame the mover is in, gathers the walls near the move
/// (<see cref="WallSet"/>), and slides the body among them (<see cref="BodySweep"/>). The path it
/// returns is then walked leg by leg by the point resolvers, which decide floors, cells and steps.
/// </summary>
internal sealed class BodyPlanner(LandblockRegistry registry, WorldFrame frame)
{
    /// <summary>
    /// The path of a body of <paramref name="body"/> with its feet at <paramref name="position"/>
    /// (world) in <paramref name="cellId"/> moving by <paramref name="delta"/>; the path's points (in <paramref name="points"/>) are
    /// landblock-local in landblock (<paramref name="lbX"/>, <paramref name="lbY"/>). False when the
    /// mover's landblock is not loaded (no walls are known: the point move decides).
    /// </summary>
    [SkipLocalsInit] // the stack buffers are written before they are read
    public bool Plan(Vector3 position, uint cellId, Vector2 delta, float stepUp, MoverBody body, Span<Vector2> points, ref BodySweep.Path path, out int lbX, out int lbY)
    {
        if (!Locate(position, cellId, out lbX, out lbY, out Vector2 local, out LandblockEntry? entry))
        {
            return false;
        }

        float skin = Skin(lbX, lbY, local, delta.Length() + body.Radius);
        float radius = body.Radius + skin;
        float reach = delta.Length() + radius + PhysicsConstants.ContactTolerance;
        Span<int> cells = stackalloc int[PhysicsConstants.MaxBodyCells];
        var walls = new WallSet(cells, local, reach);
        Gather(ref walls, entry, cellId, lbX, lbY);
        BodySweep.Slide(in walls, local, delta, radius, 0.5f * skin, position.Z + stepUp, position.Z + body.Height, points, ref path);
        return true;
    }

    /// <summary>
    /// Whether an outdoor move of <paramref name="delta"/> (not zero) needs no plan: its landblock is not
    /// loaded (the point move holds or refuses it), or no wall lies in the box the body sweeps (the move's
    /// start and end grown by the radius, skin and contact tolerance) and the box a plan gathers walls in
    /// (the start ± the move's length and that growth) stays inside the landblock. Then the body meets no
    /// wall, and the point move is its answer. Indoor moves are always planned.
    /// </summary>
    public bool IsOpenGround(Vector3 position, uint cellId, Vector2 delta, MoverBody body)
    {
        if (CellIds.IsIndoor(cellId))
        {
            return false;
        }

        frame.Locate(position, cellId, out int lbX, out int lbY, out Vector2 local);
        if (registry.Get(lbX, lbY) is not LandblockEntry entry)
        {
            return true;
        }

        // The box the body sweeps (its start and end grown by its radius, skin and the contact
        // tolerance): with no wall in it the body meets none on its way, so it does not slide, and its
        // move is the point's. (Were it to meet one, its slide could turn anywhere within the move's
        // length, which is why a plan gathers the walls around the start as far as the move reaches.)
        // The seams are tested on the plan's box, not the swept one: across a seam the plan gathers a
        // neighbour's cells, whose walls may reach back over the seam into the swept box, and this
        // landblock does not list them.
        float length = delta.Length();
        float grow = body.Radius + Skin(lbX, lbY, local, length + body.Radius) + PhysicsConstants.ContactTolerance;
        float reach = length + grow;
        Vector2 min = Vector2.Min(local, local + delta) - new Vector2(grow), max = Vector2.Max(local, local + delta) + new Vector2(grow);
        return !NearSeam(local - new Vector2(reach), local + new Vector2(reach)) && !AnyWallNear(entry, min, max, local, reach);
    }

    /// <summary>
    /// How far a body of <paramref name="body"/> with its feet at <paramref name="position"/> (world) in
    /// <paramref name="cellId"/> reaches into the walls of its height band beyond what the float rounding
    /// may leave it (the sink, half its skin), metres: above zero it overlaps a wall, and
    /// <paramref name="outward"/> is the unit normal out of the deepest. Zero when its landblock is not loaded.
    /// </summary>
    [SkipLocalsInit] // the stack buffer is written before it is read
    public float Overlap(Vector3 position, uint cellId, float stepUp, MoverBody body, out Vector2 outward)
    {
        outward = default;
        if (!Locate(position, cellId, out int lbX, out int lbY, out Vector2 local, out LandblockEntry? entry))
        {
            return 0f;
        }

        float skin = Skin(lbX, lbY, local, body.Radius);
        float radius = body.Radius + skin;
        float reach = radius + PhysicsConstants.ContactTolerance;
        Vector2 min = local - new Vector2(reach), max = local + new Vector2(reach);
        if (!CellIds.IsIndoor(cellId) && !AnyWallNear(entry, min, max, local, reach) && !NearSeam(min, max))
        {
            return -0.5f * skin; // open ground: no wall to overlap
        }

        Span<int> cells = stackalloc int[PhysicsConstants.MaxBodyCells];
        var walls = new WallSet(cells, local, radius + PhysicsConstants.ContactTolerance);
        Gather(ref walls, entry, cellId, lbX, lbY);
        float t = 1f, depth = 0f;
        Vector2 normal = default;
        walls.Sweep(local, Vector2.Zero, radius, radius, position.Z + stepUp, position.Z + body.Height, ref t, ref normal, ref depth, ref outward);
        return depth - (0.5f * skin);
    }

    /// <summary>The mover's landblock, its landblock-local position and entry; false when not loaded (or the indoor cell is unknown).</summary>
    private bool Locate(Vector3 position, uint cellId, out int lbX, out int lbY, out Vector2 local, [NotNullWhen(true)] out LandblockEntry? entry)
    {
        if (CellIds.IsIndoor(cellId))
        {
            (lbX, lbY) = (CellIds.LandblockX(cellId), CellIds.LandblockY(cellId));
            local = frame.Representable(lbX, lbY, new Vector2(position.X, position.Y) - frame.Origin(lbX, lbY));
        }
        else
        {
            frame.Locate(position, cellId, out lbX, out lbY, out local);
        }

        entry = registry.Get(lbX, lbY);
        return entry is not null && (!CellIds.IsIndoor(cellId) || entry.TryGetCellIndex(cellId, out _));
    }

    /// <summary>The cells whose walls the body may meet: through portals indoors, over the outdoor squares (and across seams) outdoors.</summary>
    private void Gather(ref WallSet walls, LandblockEntry entry, uint cellId, int lbX, int lbY)
    {
        int slot = walls.AddLandblock(entry, Vector2.Zero);
        if (CellIds.IsIndoor(cellId))
        {
            entry.TryGetCellIndex(cellId, out int cellIndex);
            GatherIndoors(ref walls, slot, entry, cellIndex);
        }
        else
        {
            GatherOutdoors(ref walls, slot, entry);
            GatherAcrossSeams(ref walls, lbX, lbY);
        }
    }

    /// <summary>
    /// The gap the body keeps from walls beyond its radius: <see cref="PhysicsConstants.BodySkin"/>
    /// plus twice the float spacing of the coordinates it may reach, in the world frame and the
    /// landblock's, so rounding the answer to the world frame never puts the body into a wall.
    /// </summary>
    private float Skin(int lbX, int lbY, Vector2 local, float reach)
    {
        Vector2 world = frame.Origin(lbX, lbY) + local;
        float largest = MathF.Max(MathF.Max(MathF.Abs(world.X), MathF.Abs(world.Y)), MathF.Max(MathF.Abs(local.X), MathF.Abs(local.Y))) + reach;
        return PhysicsConstants.BodySkin + (2f * (MathF.BitIncrement(largest) - largest));
    }

    /// <summary>
    /// Outdoors: whether any cell's or outdoor object's walls overlap the box <paramref name="min"/>–<paramref name="max"/>
    /// (within <paramref name="reach"/> of <paramref name="from"/>, per axis): what <see cref="GatherOutdoors"/>
    /// would gather for such a box, asked on its own.
    /// </summary>
    /// <remarks>
    /// Not written as <see cref="GatherOutdoors"/> into a set with no room: forming that set on every
    /// open-ground move cost the body alone 1.3× → 1.86× of <c>Player</c> without a body (measured).
    /// </remarks>
    private static bool AnyWallNear(LandblockEntry entry, Vector2 min, Vector2 max, Vector2 from, float reach)
    {
        int x0 = CellIds.OutdoorColumn(min.X), x1 = CellIds.OutdoorColumn(max.X);
        int y0 = CellIds.OutdoorColumn(min.Y), y1 = CellIds.OutdoorColumn(max.Y);
        for (int cx = x0; cx <= x1; cx++)
        {
            for (int cy = y0; cy <= y1; cy++)
            {
                foreach (int cell in entry.WallBuckets[(cx * PhysicsConstants.CellsPerSide) + cy])
                {
                    if (Overlap(entry.Cells[cell].Walls, min, max))
                    {
                        return true;
                    }
                }
            }
        }

        return entry.ObjectsMayBeWithin(from, reach) && AnyObjectWallNear(entry, min, max);
    }

    /// <summary>Whether an outdoor object listed over the fine-grid squares of the box has walls overlapping it.</summary>
    private static bool AnyObjectWallNear(LandblockEntry entry, Vector2 min, Vector2 max)
    {
        int x0 = LandblockEntry.ObjectGridColumn(min.X), x1 = LandblockEntry.ObjectGridColumn(max.X);
        int y0 = LandblockEntry.ObjectGridColumn(min.Y), y1 = LandblockEntry.ObjectGridColumn(max.Y);
        for (int cx = x0; cx <= x1; cx++)
        {
            for (int cy = y0; cy <= y1; cy++)
            {
                foreach (int o in entry.ObjectsAt(cx, cy))
                {
                    ref readonly ObjectBox b = ref entry.ObjectBoxes[o];
                    if (b.WallMin.X <= max.X && b.WallMax.X >= min.X && b.WallMin.Y <= max.Y && b.WallMax.Y >= min.Y)
                    {
                        return true;
                    }
                }
            }
        }

        return false;
    }

    private static bool Overlap(CellWalls walls, Vector2 min, Vector2 max) =>
        walls.Min.X <= max.X && walls.Max.X >= min.X && walls.Min.Y <= max.Y && walls.Max.Y >= min.Y;

    /// <summary>Whether the box reaches across one of the landblock's seams (a neighbour's walls may be in it).</summary>
    private static bool NearSeam(Vector2 min, Vector2 max) =>
        min.X < 0f || min.Y < 0f || max.X > PhysicsConstants.LandblockSize || max.Y > PhysicsConstants.LandblockSize;

    /// <summary>The mover's cell and every cell reached from it through a portal whose bounds the move's box overlaps, breadth first.</summary>
    private static void GatherIndoors(ref WallSet walls, int slot, LandblockEntry entry, int cellIndex)
    {
        walls.TryAdd(slot, cellIndex);
        for (int i = 0; i < walls.Count; i++)
        {
            int cell = walls.At(i).Cell;
            ReadOnlySpan<PortalShape> shapes = entry.Cells[cell].PortalShapes;
            int[] targets = entry.PortalTargets[cell];
            for (int k = 0; k < shapes.Length; k++)
            {
                if (targets[k] >= 0 && walls.Overlaps(shapes[k].BoundsMin, shapes[k].BoundsMax, Vector2.Zero) && !walls.TryAdd(slot, targets[k]))
                {
                    return; // full: the nearest cells are in
                }
            }
        }
    }

    /// <summary>
    /// The cells of a landblock listed over the outdoor squares the move's box covers, and its outdoor
    /// objects listed over the fine-grid squares it covers, whose walls the box overlaps. False when the
    /// set filled (the nearest are in).
    /// </summary>
    private static bool GatherOutdoors(ref WallSet walls, int slot, LandblockEntry entry)
    {
        (_, Vector2 offset) = walls.Slot(slot);
        Vector2 min = walls.BoxMin - offset, max = walls.BoxMax - offset;
        if (max.X < -PhysicsConstants.LandblockSize || max.Y < -PhysicsConstants.LandblockSize
            || min.X > 2 * PhysicsConstants.LandblockSize || min.Y > 2 * PhysicsConstants.LandblockSize)
        {
            return true;
        }

        int x0 = CellIds.OutdoorColumn(min.X), x1 = CellIds.OutdoorColumn(max.X);
        int y0 = CellIds.OutdoorColumn(min.Y), y1 = CellIds.OutdoorColumn(max.Y);
        for (int cx = x0; cx <= x1; cx++)
        {
            for (int cy = y0; cy <= y1; cy++)
            {
                foreach (int cell in entry.WallBuckets[(cx * PhysicsConstants.CellsPerSide) + cy])
                {
                    CellWalls cellWalls = entry.Cells[cell].Walls;
                    if (walls.Overlaps(cellWalls.Min, cellWalls.Max, offset) && !walls.TryAdd(slot, cell))
                    {
                        return false;
                    }
                }
            }
        }

        if (entry.OutdoorObjects.Length == 0)
        {
            return true;
        }

        x0 = LandblockEntry.ObjectGridColumn(min.X);
        x1 = LandblockEntry.ObjectGridColumn(max.X);
        y0 = LandblockEntry.ObjectGridColumn(min.Y);
        y1 = LandblockEntry.ObjectGridColumn(max.Y);
        for (int cx = x0; cx <= x1; cx++)
        {
            for (int cy = y0; cy <= y1; cy++)
            {
                foreach (int o in entry.ObjectsAt(cx, cy))
                {
                    ref readonly ObjectBox b = ref entry.ObjectBoxes[o];
                    if (walls.Overlaps(b.WallMin, b.WallMax, offset) && !walls.TryAdd(slot, WallSet.ObjectFlag | o))
                    {
                        return false;
                    }
                }
            }
        }

        return true;
    }

    /// <summary>Outdoors near a seam: the neighbour landblocks the move's box reaches into, each in its offset.</summary>
    private void GatherAcrossSeams(ref WallSet walls, int lbX, int lbY)
    {
        const float size = PhysicsConstants.LandblockSize;
        int dx = walls.BoxMin.X < 0f ? -1 : walls.BoxMax.X > size ? 1 : 0;
        int dy = walls.BoxMin.Y < 0f ? -1 : walls.BoxMax.Y > size ? 1 : 0;
        Neighbour(ref walls, lbX, lbY, dx, 0);
        Neighbour(ref walls, lbX, lbY, 0, dy);
        if (dx != 0 && dy != 0)
        {
            Neighbour(ref walls, lbX, lbY, dx, dy);
        }
    }

    private void Neighbour(ref WallSet walls, int lbX, int lbY, int dx, int dy)
    {
        if ((dx == 0 && dy == 0) || !CellIds.IsInWorld(lbX + dx, lbY + dy) || registry.Get(lbX + dx, lbY + dy) is not LandblockEntry neighbour)
        {
            return;
        }

        int slot = walls.AddLandblock(neighbour, new Vector2(dx * PhysicsConstants.LandblockSize, dy * PhysicsConstants.LandblockSize));
        GatherOutdoors(ref walls, slot, neighbour);
    }
}
