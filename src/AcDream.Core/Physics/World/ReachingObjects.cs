using System.Numerics;
using AcDream.Core.Physics.Surfaces;

namespace AcDream.Core.Physics.World;

/// <summary>An object standing in another cell that reaches into a cell's space: the index of the cell it stands in, and the object.</summary>
internal readonly record struct ReachingObject(int Cell, ObjectSurface Object);

/// <summary>
/// Which objects standing in a landblock's cells reach into other cells: a stair standing in a cellar whose top rises
/// through the floor opening into the shaft above it is in the shaft's space too. A cast in a cell meets these as well
/// as the cell's own (a path that stays in the shaft never passes into the cellar).
/// </summary>
internal static class ReachingObjects
{
    /// <summary>
    /// Per cell of <paramref name="cells"/>: the objects standing in the others whose bounds meet its space (the box of its
    /// walls, floors and portals, edges included), in the order of the cells they stand in and of their objects there.
    /// </summary>
    public static ReachingObject[][] Build(CellSurface[] cells)
    {
        var standing = new List<ReachingObject>();
        for (int c = 0; c < cells.Length; c++)
        {
            foreach (ObjectSurface o in cells[c].Objects)
            {
                standing.Add(new ReachingObject(c, o));
            }
        }

        var result = new ReachingObject[cells.Length][];
        var found = new List<ReachingObject>();
        for (int d = 0; d < cells.Length; d++)
        {
            if (standing.Count == 0)
            {
                result[d] = []; // (no objects in cells: nothing to find)
                continue;
            }

            found.Clear();
            Space3 space = Space(cells[d]);
            foreach (ReachingObject o in standing)
            {
                if (o.Cell != d && space.Meets(o.Object.BoundsMin, o.Object.BoundsMax))
                {
                    found.Add(o);
                }
            }

            result[d] = found.Count == 0 ? [] : [.. found];
        }

        return result;
    }

    /// <summary>The box of a cell's own walls, floors and portals (not its objects'), landblock-local metres.</summary>
    private static Space3 Space(CellSurface cell)
    {
        var space = Space3.Empty;
        CellWalls walls = cell.Walls;
        if (walls.Polygons.Length > 0)
        {
            space = space.With(new Vector3(walls.Min, walls.ZMin), new Vector3(walls.Max, walls.ZMax));
        }

        if (cell.HasFloor)
        {
            space = space.With(new Vector3(cell.FloorMin, cell.FloorZMin), new Vector3(cell.FloorMax, cell.FloorZMax));
        }

        foreach (PortalShape p in cell.PortalShapes)
        {
            space = space.With(new Vector3(p.BoundsMin, p.ZMin), new Vector3(p.BoundsMax, p.ZMax));
        }

        return space;
    }

    private readonly record struct Space3(Vector3 Min, Vector3 Max)
    {
        public static Space3 Empty => new(new Vector3(float.MaxValue), new Vector3(float.MinValue));

        public Space3 With(Vector3 min, Vector3 max) => new(Vector3.Min(Min, min), Vector3.Max(Max, max));

        public bool Meets(Vector3 min, Vector3 max) =>
            min.X <= Max.X && max.X >= Min.X && min.Y <= Max.Y && max.Y >= Min.Y && min.Z <= Max.Z && max.Z >= Min.Z;
    }
}
