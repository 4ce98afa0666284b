using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Casting;

// WorldCast's walk: the pieces of the path, in a cell through its portals and outdoors cell by cell.
internal static partial class WorldCast
{
    /// <summary>The walk's fixed state: the start's landblock (the cast's frame) and the options.</summary>
    [SkipLocalsInit] // the vertex buffers are written before they are read
    private readonly partial struct Walk(int x0, int y0, CastOptions options)
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
                ray.Stop(exit, new D3(n.X, n.Y, n.Z), new ShapeName(SurfaceKind.CellWall, here.CellId));
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
                ray.Polygon(rectangle, new ShapeName(SurfaceKind.CellWall, cellId), SurfaceKind.CellWall);
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
                ray.Polygon(v, new ShapeName(named, cellId), named);
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
                        ray.Stop(t0, back, new ShapeName(SurfaceKind.None, 0)); // land not loaded (or off the world): the cast ends where it begins
                    }

                    piece.Done = true;
                    return;
                }

                D3 offset = OffsetOf(entry);
                Box box = Box.Of(in ray, t0, t1, offset);
                Terrain(ref ray, ref lands, t0, t1);
                Things(ref ray, ref lands, entry, offset, in box);
                Movers(ref ray, ref lands, entry, offset, in box);
                (double door, int cell) = Doorway(in ray, entry, offset, cx - ((lx - _x0) * PhysicsConstants.CellsPerSide), cy - ((ly - _y0) * PhysicsConstants.CellsPerSide), (t0, t1, piece.Slack));
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
    }
}
