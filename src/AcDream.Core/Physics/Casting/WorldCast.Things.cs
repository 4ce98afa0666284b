using System.Numerics;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Movers;

namespace AcDream.Core.Physics.Casting;

// WorldCast's walk, what a piece meets: things outdoors, the terrain, the movers near and the doorways over the path.
internal static partial class WorldCast
{
    private readonly partial struct Walk
    {
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
                        var heights = new CornerHeights(sw, se, nw, ne);
                        ray.BilinearCell(x, y, Column, in heights, id);
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
            ray.Polygon(v, new ShapeName(SurfaceKind.Terrain, id), SurfaceKind.Terrain);
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

        /// <summary>
        /// The earliest fraction in the stretch's <c>T0</c>..<c>T1</c> at which the centre passes in through a doorway of a
        /// cell over terrain cell (cx, cy) of <paramref name="entry"/>, and that cell's index; +∞ and −1 for none. A doorway
        /// at the stretch's start counts within its <c>Slack</c> (metres) beyond its plane (<see cref="Piece.Slack"/>).
        /// </summary>
        private static (double T, int Cell) Doorway(in SweptSphere ray, LandblockEntry entry, D3 offset, int cx, int cy, (double T0, double T1, double Slack) stretch)
        {
            (double t0, double t1, double slack) = stretch;
            int cell = -1;
            double best = double.PositiveInfinity;
            if ((uint)cx >= PhysicsConstants.CellsPerSide || (uint)cy >= PhysicsConstants.CellsPerSide)
            {
                return (best, cell);
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

            return (best, cell);
        }
    }
}
