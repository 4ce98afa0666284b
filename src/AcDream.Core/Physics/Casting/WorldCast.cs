using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics;

/// <summary>
/// A cast through the world (<see cref="PhysicsEngine.Cast"/>): the sphere's centre followed piece by piece, in a cell
/// or outdoors, and in each piece every shape the sphere can reach there tested (<see cref="SweptSphere"/>), in the
/// landblock-local frame of the start.
/// </summary>
/// <remarks>
/// <para>
/// In a cell: the shapes of the cell, of every cell reached from it through portals whose bounds meet the rest of the
/// path (grown by the radius), of the objects standing in them and of those standing in other cells that reach into
/// them (<see cref="LandblockEntry.Reaching"/>); near a portal to the outdoors, also the outdoor
/// objects and the walls of the building's cells within the radius of that portal (a shell's door frame); the movers
/// near. The centre leaves the cell through the first portal its segment passes out through: on into the neighbour,
/// or outdoors; a portal to a cell that is not loaded stops it as a wall.
/// </para>
/// <para>
/// Outdoors: the centre's path is walked 24 m terrain cell by cell (across seams: the cell's landblock, in the
/// start's frame); in each the terrain, outdoor objects, the walls of buildings' cells met from outdoors and the
/// movers within the radius of that stretch of the path are tested, and the doorways of the cells over it: a centre
/// passing in through one goes on in that cell. The walk ends at the first stretch that holds the earliest contact
/// found, so its cost grows with the cells crossed, not the landblock's size. A stretch in a landblock that is not
/// loaded (or off the world) stops the cast where it begins.
/// </para>
/// </remarks>
internal static partial class WorldCast
{
    private const float Size = PhysicsConstants.LandblockSize;
    private const double Column = PhysicsConstants.CellSize;

    /// <summary>Where the centre is while the cast walks: the landblock, the cell (−1 outdoors) and the fraction it got there.</summary>
    private struct Piece
    {
        public LandblockEntry Entry;
        public int Cell;
        public double From;
        public bool Done;

        /// <summary>
        /// How far beyond a portal's plane (metres) the centre may be and still pass through it at once: at the start, the
        /// world frame's rounding of the start (a cast from another's rounded answer); after a crossing, none (the next
        /// crossing must come later, so two portals meeting at an edge cannot hand the centre back and forth).
        /// </summary>
        public double Slack;
    }

    public static CastHit Run(in WorldFrame frame, ref Neighbourhood lands, in Place start, Vector3 from, Vector3 to, in CastOptions options)
    {
        var origin = new D3(start.Local.X, start.Local.Y, from.Z);
        var move = new D3((double)to.X - from.X, (double)to.Y - from.Y, (double)to.Z - from.Z);
        var ray = new SweptSphere(origin, move, options.Radius);
        float rounding = 2f * MathF.Max(Geometry.Spacing(MathF.Abs(from.X)), MathF.Max(Geometry.Spacing(MathF.Abs(from.Y)), Geometry.Spacing(MathF.Abs(from.Z))));
        var piece = new Piece { Entry = start.Entry, Cell = start.CellIndex, Slack = Math.Max(PhysicsConstants.EdgeTolerance, rounding) };
        var cast = new Walk(start.X, start.Y, options);
        for (int visit = 0; visit < PhysicsConstants.MaxCellVisits && !piece.Done; visit++)
        {
            if (piece.Cell >= 0)
            {
                cast.Indoors(ref ray, ref lands, ref piece);
            }
            else
            {
                cast.Outdoors(ref ray, ref lands, ref piece);
            }
        }

        if (!piece.Done && piece.From < ray.T)
        {
            // Out of visits: the rest of the path was not looked at, so the cast ends where the last piece began.
            ray.Stop(piece.From, -move * (1.0 / Math.Max(move.Length, double.Epsilon)), SurfaceKind.None, 0);
        }

        double t = Math.Min(ray.T, 1.0);
        D3 centre = ray.At(t);
        (int lx, int ly, Vector2 local) = cast.Landblock(centre);
        uint cellId = piece.Cell >= 0 ? piece.Entry.Cells[piece.Cell].CellId : WorldFrame.OutdoorCellId(lx, ly, local);
        if (!ray.Found)
        {
            return new CastHit(false, 1f, to, to, Vector3.Zero, SurfaceKind.None, 0, cellId);
        }

        Vector3 position = frame.ToWorld(start.X, start.Y, new Vector2((float)centre.X, (float)centre.Y), (float)centre.Z);
        D3 touch = centre - (ray.Normal * ray.Radius);
        Vector3 point = frame.ToWorld(start.X, start.Y, new Vector2((float)touch.X, (float)touch.Y), (float)touch.Z);
        return new CastHit(true, (float)t, position, point, ray.Normal.ToVector3(), ray.Kind, ray.Id, cellId);
    }

    /// <summary>The walk's fixed state: the start's landblock (the cast's frame) and the options.</summary>
    [SkipLocalsInit] // the vertex buffers are written before they are read
    private readonly struct Walk(int x0, int y0, CastOptions options)
    {
        private readonly int _x0 = x0, _y0 = y0;
        private readonly CastOptions _options = options;

        /// <summary>The landblock a point of the cast's frame is in, and its local XY there.</summary>
        public (int X, int Y, Vector2 Local) Landblock(D3 p)
        {
            int dx = (int)Math.Floor(p.X / Size), dy = (int)Math.Floor(p.Y / Size);
            return (_x0 + dx, _y0 + dy, new Vector2((float)(p.X - (dx * (double)Size)), (float)(p.Y - (dy * (double)Size))));
        }

        /// <summary>The offset of a landblock's frame in the cast's: a point of its frame plus this is in the cast's.</summary>
        private D3 OffsetOf(LandblockEntry entry) => new((entry.X - _x0) * (double)Size, (entry.Y - _y0) * (double)Size, 0);

        /// <summary>The piece in a cell: its shapes and its neighbours' tested, then the centre's way out of it.</summary>
        public void Indoors(ref SweptSphere ray, ref Neighbourhood lands, ref Piece piece)
        {
            LandblockEntry entry = piece.Entry;
            D3 offset = OffsetOf(entry);
            Box box = Box.Of(in ray, piece.From, Math.Min(ray.T, 1.0), offset); // (nothing beyond a contact found counts)

            // The cells whose portals' bounds the rest of the path meets, breadth first from the centre's.
            Span<int> cells = stackalloc int[PhysicsConstants.MaxCellVisits];
            int count = 1;
            cells[0] = piece.Cell;
            bool outdoors = false;
            Box doors = Box.Empty;
            for (int i = 0; i < count; i++)
            {
                CellSurface cell = entry.Cells[cells[i]];
                ReadOnlySpan<PortalShape> portals = cell.PortalShapes;
                int[] targets = entry.PortalTargets[cells[i]];
                for (int k = 0; k < portals.Length; k++)
                {
                    PortalShape p = portals[k];
                    if (!box.Meets(p.BoundsMin, p.BoundsMax, p.ZMin, p.ZMax))
                    {
                        continue;
                    }

                    if (targets[k] == LandblockEntry.OutdoorTarget)
                    {
                        outdoors = true;
                        doors = doors.With(new Box(p.BoundsMin, p.BoundsMax, p.ZMin, p.ZMax));
                    }
                    else if (targets[k] == LandblockEntry.MissingCell)
                    {
                        Closed(ref ray, p, offset, cell.CellId); // a portal to a cell not registered: a wall
                    }
                    else if (targets[k] >= 0 && count < cells.Length && !cells[..count].Contains(targets[k]))
                    {
                        cells[count++] = targets[k];
                    }
                }
            }

            for (int i = 0; i < count; i++)
            {
                Cell(ref ray, entry.Cells[cells[i]], offset, in box);
                foreach (ReachingObject o in entry.Reaching[cells[i]])
                {
                    if (!cells[..count].Contains(o.Cell))
                    {
                        Object(ref ray, o.Object, offset, in box); // standing in a cell not listed, rising into this one
                    }
                }
            }

            if (outdoors)
            {
                // What stands outside the doors, met only where the sphere is near them (a shell's base under the house
                // is not met from inside it).
                Box near = doors.Grown((float)ray.Radius + PhysicsConstants.EdgeTolerance).Within(in box);
                if (!near.IsEmpty && near.Grown((float)ray.Radius).Span(in ray, offset, piece.From) is (double from, double to))
                {
                    ray.Within(from, to);
                    Things(ref ray, ref lands, entry, offset, in near);
                    ray.Everywhere();
                }
            }

            Movers(ref ray, ref lands, entry, offset, in box);

            // The centre's way out: the first portal of its cell it passes out through.
            CellSurface here = entry.Cells[piece.Cell];
            ReadOnlySpan<PortalShape> own = here.PortalShapes;
            double exit = double.PositiveInfinity;
            int through = -1;
            for (int k = 0; k < own.Length; k++)
            {
                double t = Crossing(in ray, own[k], offset, piece.From, piece.Slack, outward: true);
                if (t < exit)
                {
                    (exit, through) = (t, k);
                }
            }

            if (through < 0 || ray.T <= exit)
            {
                piece.Done = true;
                return;
            }

            int target = entry.PortalTargets[piece.Cell][through];
            if (target == LandblockEntry.MissingCell)
            {
                Vector3 n = -own[through].OutNormal;
                ray.Stop(exit, new D3(n.X, n.Y, n.Z), SurfaceKind.CellWall, here.CellId);
                piece.Done = true;
                return;
            }

            (piece.Cell, piece.From, piece.Slack) = (target, exit, 0);
        }

        /// <summary>A portal as a surface of its cell: a doorway's rectangle in its plane (a wall), an opening's outline on its plane (the ceiling or floor it is cut in).</summary>
        private static void Closed(ref SweptSphere ray, PortalShape p, D3 offset, uint cellId)
        {
            D3 rel = offset - ray.Start;
            if (p.Kind == PortalKind.Vertical)
            {
                double ox = p.Origin.X + rel.X, oy = p.Origin.Y + rel.Y, tx = p.Tangent.X, ty = p.Tangent.Y;
                double z0 = p.ZMin + rel.Z, z1 = p.ZMax + rel.Z;
                ReadOnlySpan<D3> rectangle =
                [
                    new(ox + (tx * p.TMin), oy + (ty * p.TMin), z0), new(ox + (tx * p.TMax), oy + (ty * p.TMax), z0),
                    new(ox + (tx * p.TMax), oy + (ty * p.TMax), z1), new(ox + (tx * p.TMin), oy + (ty * p.TMin), z1),
                ];
                ray.Polygon(rectangle, SurfaceKind.CellWall, cellId, SurfaceKind.CellWall);
            }
            else if (p.Kind == PortalKind.Horizontal && p.Outline.Length <= PhysicsConstants.MaxWallPolygonVertices)
            {
                Span<D3> v = stackalloc D3[p.Outline.Length];
                for (int i = 0; i < v.Length; i++)
                {
                    Vector2 q = p.Outline[i];
                    v[i] = new D3(q.X + rel.X, q.Y + rel.Y, p.PlaneZ(q.X, q.Y) + rel.Z);
                }

                SurfaceKind named = p.OutNormal.Z > 0 ? SurfaceKind.CellCeiling : SurfaceKind.CellFloor; // an opening in the ceiling, or in the floor
                ray.Polygon(v, named, cellId, named);
            }
        }

        /// <summary>The piece outdoors: the path walked terrain cell by terrain cell until a stretch holds the earliest contact, or the centre passes in through a doorway.</summary>
        public void Outdoors(ref SweptSphere ray, ref Neighbourhood lands, ref Piece piece)
        {
            D3 p = ray.At(piece.From), d = ray.Move;
            int cx = (int)Math.Floor(p.X / Column), cy = (int)Math.Floor(p.Y / Column);
            int stepX = d.X > 0 ? 1 : d.X < 0 ? -1 : 0, stepY = d.Y > 0 ? 1 : d.Y < 0 ? -1 : 0;
            (cx, cy) = (stepX < 0 && p.X == cx * Column ? cx - 1 : cx, stepY < 0 && p.Y == cy * Column ? cy - 1 : cy); // on a line, moving back: the cell it enters

            // Come out of a cell: what lies outdoors is met from the doorway on (not the ground under the house behind it).
            if (piece.From > 0)
            {
                ray.Within(piece.From, 1.0);
            }

            double nextX = stepX == 0 ? double.PositiveInfinity : (((cx + (stepX > 0 ? 1 : 0)) * Column) - ray.Start.X) / d.X;
            double nextY = stepY == 0 ? double.PositiveInfinity : (((cy + (stepY > 0 ? 1 : 0)) * Column) - ray.Start.Y) / d.Y;
            double deltaX = stepX == 0 ? 0 : Column / Math.Abs(d.X), deltaY = stepY == 0 ? 0 : Column / Math.Abs(d.Y);
            double t0 = piece.From;
            while (true)
            {
                double t1 = Math.Min(Math.Min(nextX, nextY), 1.0);
                int lx = _x0 + FloorDiv(cx, PhysicsConstants.CellsPerSide), ly = _y0 + FloorDiv(cy, PhysicsConstants.CellsPerSide);
                if (!CellIds.IsInWorld(lx, ly) || lands.Get(lx, ly) is not LandblockEntry entry)
                {
                    ray.Everywhere();
                    if (t0 < ray.T)
                    {
                        D3 back = -d * (1.0 / Math.Max(d.Length, double.Epsilon));
                        ray.Stop(t0, back, SurfaceKind.None, 0); // land not loaded (or off the world): the cast ends where it begins
                    }

                    piece.Done = true;
                    return;
                }

                D3 offset = OffsetOf(entry);
                Box box = Box.Of(in ray, t0, t1, offset);
                Terrain(ref ray, ref lands, t0, t1);
                Things(ref ray, ref lands, entry, offset, in box);
                Movers(ref ray, ref lands, entry, offset, in box);
                double door = Doorway(in ray, entry, offset, cx - ((lx - _x0) * PhysicsConstants.CellsPerSide), cy - ((ly - _y0) * PhysicsConstants.CellsPerSide), t0, t1, piece.Slack, out int cell);
                if (door < ray.T && door <= t1)
                {
                    // In through a doorway: every contact found is later than it, and what the centre meets from here is the
                    // building's (the terrain under a floor, a wall's outer face from inside, are not met indoors).
                    ray.Everywhere();
                    ray.Forget();
                    (piece.Entry, piece.Cell, piece.From, piece.Slack) = (entry, cell, door, 0);
                    return;
                }

                if (ray.T <= t1 || t1 >= 1.0)
                {
                    ray.Everywhere();
                    piece.Done = true;
                    return;
                }

                t0 = t1;
                if (nextX <= nextY)
                {
                    (cx, nextX) = (cx + stepX, nextX + deltaX);
                }
                else
                {
                    (cy, nextY) = (cy + stepY, nextY + deltaY);
                }
            }
        }

        /// <summary>
        /// What stands outdoors within the box (the frame of <paramref name="entry"/>, at <paramref name="offset"/> in the
        /// cast's): its outdoor objects and the walls of its cells met from outdoors; the same of every neighbour whose things
        /// reach into the box.
        /// </summary>
        private void Things(ref SweptSphere ray, ref Neighbourhood lands, LandblockEntry entry, D3 offset, in Box box)
        {
            Outdoor(ref ray, entry, offset, in box);
            SeamNeighbours across = Neighbourhood.Across(ref lands, entry, box.Lo, box.Hi);
            while (across.MoveNext())
            {
                Vector2 o = across.Offset;
                Box there = box.Moved(-o);
                Outdoor(ref ray, across.Current, offset + new D3(o.X, o.Y, 0), in there);
            }
        }

        private void Outdoor(ref SweptSphere ray, LandblockEntry entry, D3 offset, in Box box)
        {
            if (entry.OutdoorCellWalls is BoxGrid walls)
            {
                for (BoxGrid.Cursor near = walls.Near(box.Lo, box.Hi); near.MoveNext();)
                {
                    CellSurface cell = entry.Cells[near.Current];
                    Walls(ref ray, cell.Walls, offset, in box, new Names(SurfaceKind.CellWall, SurfaceKind.CellCeiling, SurfaceKind.CellWall, cell.CellId));
                }
            }

            ObjectSurface[] objects = entry.OutdoorObjects;
            for (BoxGrid.Cursor near = entry.Objects.Near(box.Lo, box.Hi); near.MoveNext();)
            {
                Object(ref ray, objects[near.Current], offset, in box);
            }
        }

        /// <summary>
        /// The terrain triangles (or bilinear cells) within the radius of the centre's path from <paramref name="t0"/> to
        /// <paramref name="t1"/>, in whichever landblocks they are: the terrain cells its box (grown by the radius, in
        /// double precision, with no margin: a point on a cell's edge is on both cells' triangles, whose shared edge the
        /// face test holds within its tolerance) covers, less those wholly above or below it.
        /// </summary>
        private void Terrain(ref SweptSphere ray, ref Neighbourhood lands, double t0, double t1)
        {
            int per = PhysicsConstants.CellsPerSide;
            D3 a = ray.At(t0), b = ray.At(t1);
            double r = ray.Radius, zLo = Math.Min(a.Z, b.Z) - r - PhysicsConstants.CastEdgeTolerance, zHi = Math.Max(a.Z, b.Z) + r + PhysicsConstants.CastEdgeTolerance;
            int c0 = (int)Math.Floor((Math.Min(a.X, b.X) - r) / Column), c1 = (int)Math.Floor((Math.Max(a.X, b.X) + r) / Column);
            int r0 = (int)Math.Floor((Math.Min(a.Y, b.Y) - r) / Column), r1 = (int)Math.Floor((Math.Max(a.Y, b.Y) + r) / Column);
            Span<D3> v = stackalloc D3[3];
            for (int c = c0; c <= c1; c++)
            {
                for (int row = r0; row <= r1; row++)
                {
                    int lx = _x0 + FloorDiv(c, per), ly = _y0 + FloorDiv(row, per);
                    if (!CellIds.IsInWorld(lx, ly) || lands.Get(lx, ly) is not LandblockEntry entry)
                    {
                        continue;
                    }

                    int cx = c - ((lx - _x0) * per), cy = row - ((ly - _y0) * per);
                    TerrainSurface terrain = entry.Terrain;
                    terrain.Corners(cx, cy, out double sw, out double nw, out double se, out double ne);
                    if (Math.Max(Math.Max(sw, nw), Math.Max(se, ne)) < zLo || Math.Min(Math.Min(sw, nw), Math.Min(se, ne)) > zHi)
                    {
                        continue; // the path's stretch is wholly above or below this cell's ground
                    }

                    uint id = CellIds.Prefix(lx, ly) | (uint)((cx * per) + cy + 1);
                    double x = (c * Column) - ray.Start.X, y = (row * Column) - ray.Start.Y, z = -ray.Start.Z;
                    (sw, nw, se, ne) = (sw + z, nw + z, se + z, ne + z);
                    if (terrain.LandblockId is null)
                    {
                        ray.BilinearCell(x, y, Column, sw, se, nw, ne, id);
                        continue;
                    }

                    D3 pSW = new(x, y, sw), pSE = new(x + Column, y, se), pNW = new(x, y + Column, nw), pNE = new(x + Column, y + Column, ne);
                    if (terrain.IsSplitSwToNe(cx, cy))
                    {
                        Triangle(ref ray, v, pSW, pSE, pNE, id);
                        Triangle(ref ray, v, pSW, pNE, pNW, id);
                    }
                    else
                    {
                        Triangle(ref ray, v, pSW, pSE, pNW, id);
                        Triangle(ref ray, v, pNE, pNW, pSE, id);
                    }
                }
            }
        }

        private static void Triangle(ref SweptSphere ray, Span<D3> v, D3 a, D3 b, D3 c, uint id)
        {
            (v[0], v[1], v[2]) = (a, b, c);
            ray.Polygon(v, SurfaceKind.Terrain, id, SurfaceKind.Terrain);
        }

        /// <summary>The movers within the box that the cast's filters do not pass (itself is never listed): those filed in the squares near the box, not the call's.</summary>
        private void Movers(ref SweptSphere ray, ref Neighbourhood lands, LandblockEntry entry, D3 offset, in Box box)
        {
            if (lands.Movers is not MoverFrame movers)
            {
                return;
            }

            Span<D3> v = stackalloc D3[PhysicsConstants.MaxWallPolygonVertices];
            for (Neighbourhood.AlongCursor near = lands.MoversAlong(entry.X, entry.Y, new WallBox(box.Lo, box.Hi, box.ZLo, box.ZHi)); near.MoveNext();)
            {
                int j = near.Current;
                ref readonly MoverState state = ref movers.States[j];
                if (((_options.Filter & CastFilter.IgnoreCreatures) != 0 && state.IsCreature)
                    || ((_options.Filter & CastFilter.SolidOnly) != 0 && (state.Physics & PhysicsStateFlags.Ethereal) != 0))
                {
                    continue;
                }

                D3 at = offset + new D3(near.Offset.X, near.Offset.Y, 0);
                Walls(ref ray, movers.Walls[j], at, box.Moved(-near.Offset), new Names(SurfaceKind.Mover, SurfaceKind.Mover, SurfaceKind.Mover, movers.Ids[j]));
            }
        }

        /// <summary>The earliest fraction in t0..t1 at which the centre passes in through a doorway of a cell over terrain cell (cx, cy) of <paramref name="entry"/>; +∞ for none.</summary>
        private static double Doorway(in SweptSphere ray, LandblockEntry entry, D3 offset, int cx, int cy, double t0, double t1, double slack, out int cell)
        {
            cell = -1;
            double best = double.PositiveInfinity;
            if ((uint)cx >= PhysicsConstants.CellsPerSide || (uint)cy >= PhysicsConstants.CellsPerSide)
            {
                return best;
            }

            foreach (int c in entry.EntryBuckets[(cx * PhysicsConstants.CellsPerSide) + cy])
            {
                ReadOnlySpan<PortalShape> portals = entry.Cells[c].PortalShapes;
                int[] targets = entry.PortalTargets[c];
                for (int k = 0; k < portals.Length; k++)
                {
                    if (targets[k] != LandblockEntry.OutdoorTarget)
                    {
                        continue;
                    }

                    double t = Crossing(in ray, portals[k], offset, t0, t0 == 0 ? slack : 0, outward: false);
                    if (t <= t1 && t < best)
                    {
                        (best, cell) = (t, c);
                    }
                }
            }

            return best;
        }
    }

    /// <summary>
    /// The fraction at which the centre passes through the portal's opening, out of its cell (<paramref name="outward"/>)
    /// or into it; +∞ when it does not before the end. With a <paramref name="slack"/>, a centre on the plane or beyond it
    /// by no more than that, moving through, passes at <paramref name="from"/>; without, only later than
    /// <paramref name="from"/>.
    /// </summary>
    private static double Crossing(in SweptSphere ray, PortalShape portal, D3 offset, double from, double slack, bool outward)
    {
        Vector3 n = portal.OutNormal;
        if (portal.Kind == PortalKind.Degenerate)
        {
            return double.PositiveInfinity;
        }

        var normal = new D3(n.X, n.Y, n.Z);
        D3 o = offset + new D3(portal.Origin.X, portal.Origin.Y, portal.Origin.Z);
        double d0 = D3.Dot(normal, ray.At(from) - o), rate = D3.Dot(normal, ray.Move);
        double sign = outward ? 1 : -1;
        (d0, rate) = (d0 * sign, rate * sign);
        if (!(rate > 0) || d0 > slack || (slack == 0 && d0 >= 0))
        {
            return double.PositiveInfinity; // moving away from it, along it, or already beyond
        }

        double t = from + Math.Max(-d0 / rate, 0.0);
        if (t > 1.0)
        {
            return double.PositiveInfinity;
        }

        D3 at = ray.At(t) - o;
        const double tol = PhysicsConstants.EdgeTolerance;
        if (portal.Kind == PortalKind.Horizontal)
        {
            return portal.ContainsXY((float)(at.X + o.X - offset.X), (float)(at.Y + o.Y - offset.Y)) ? t : double.PositiveInfinity;
        }

        double along = (portal.Tangent.X * at.X) + (portal.Tangent.Y * at.Y);
        double z = at.Z + o.Z;
        return along >= portal.TMin - tol && along <= portal.TMax + tol && z >= portal.ZMin - tol && z <= portal.ZMax + tol ? t : double.PositiveInfinity;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int FloorDiv(int a, int b) => a >= 0 ? a / b : -((-a + b - 1) / b);

    /// <summary>A box of one landblock's frame, metres: seen from above and in height (empty when lo &gt; hi).</summary>
    private readonly record struct Box(Vector2 Lo, Vector2 Hi, float ZLo, float ZHi)
    {
        public static Box Empty => new(new Vector2(float.MaxValue), new Vector2(float.MinValue), float.MaxValue, float.MinValue);

        public bool IsEmpty => !(Lo.X <= Hi.X && Lo.Y <= Hi.Y && ZLo <= ZHi);

        /// <summary>The sphere's path from t0 to t1, in the frame at <paramref name="offset"/>, grown by its radius and a margin for rounding to floats.</summary>
        public static Box Of(in SweptSphere ray, double t0, double t1, D3 offset)
        {
            D3 a = ray.At(t0) - offset, b = ray.At(t1) - offset;
            double grow = ray.Radius + PhysicsConstants.CastBoxMargin;
            return new Box(
                new Vector2((float)(Math.Min(a.X, b.X) - grow), (float)(Math.Min(a.Y, b.Y) - grow)),
                new Vector2((float)(Math.Max(a.X, b.X) + grow), (float)(Math.Max(a.Y, b.Y) + grow)),
                (float)(Math.Min(a.Z, b.Z) - grow),
                (float)(Math.Max(a.Z, b.Z) + grow));
        }

        public bool Meets(Vector2 lo, Vector2 hi, float zLo, float zHi) =>
            lo.X <= Hi.X && hi.X >= Lo.X && lo.Y <= Hi.Y && hi.Y >= Lo.Y && zLo <= ZHi && zHi >= ZLo;

        public Box With(Box other) =>
            new(Vector2.Min(Lo, other.Lo), Vector2.Max(Hi, other.Hi), MathF.Min(ZLo, other.ZLo), MathF.Max(ZHi, other.ZHi));

        public Box Grown(float by) => new(Lo - new Vector2(by), Hi + new Vector2(by), ZLo - by, ZHi + by);

        public Box Within(in Box other) =>
            new(Vector2.Max(Lo, other.Lo), Vector2.Min(Hi, other.Hi), MathF.Max(ZLo, other.ZLo), MathF.Min(ZHi, other.ZHi));

        public Box Moved(Vector2 by) => new(Lo + by, Hi + by, ZLo, ZHi);

        /// <summary>The fractions, from <paramref name="from"/> on, at which the centre is in this box (the frame at <paramref name="offset"/>); null when never.</summary>
        public (double From, double To)? Span(in SweptSphere ray, D3 offset, double from)
        {
            D3 p = ray.Start - offset, d = ray.Move;
            double t0 = from, t1 = 1.0;
            Clip(p.X, d.X, Lo.X, Hi.X, ref t0, ref t1);
            Clip(p.Y, d.Y, Lo.Y, Hi.Y, ref t0, ref t1);
            Clip(p.Z, d.Z, ZLo, ZHi, ref t0, ref t1);
            return t0 <= t1 ? (t0, t1) : null;

            static void Clip(double p0, double dp, double lo, double hi, ref double t0, ref double t1)
            {
                if (dp == 0)
                {
                    if (p0 < lo || p0 > hi)
                    {
                        (t0, t1) = (1, 0);
                    }

                    return;
                }

                double a = (lo - p0) / dp, b = (hi - p0) / dp;
                (t0, t1) = (Math.Max(t0, Math.Min(a, b)), Math.Min(t1, Math.Max(a, b)));
            }
        }
    }
}
