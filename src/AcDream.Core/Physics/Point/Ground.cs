using System.Numerics;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Point;

/// <summary>
/// The one ground probe of the host's questions: what a mover with its feet at a place stands on, as the
/// resolvers sample it (the terrain or the cell's floor nearest the feet, raised to an object's floor no more
/// than a step above the feet, on to rest), with its kind, id and normal.
/// </summary>
internal static class Ground
{
    /// <summary>
    /// The ground under <paramref name="place"/> for feet at <paramref name="feetZ"/> and step <paramref name="stepUp"/>:
    /// its Z (<paramref name="z"/>, metres) and what it is (<paramref name="floor"/>: terrain with the outdoor cell's id,
    /// a cell's floor with the cell's, an object's floor with the object's GfxObj or Setup id; the unit normal up).
    /// False when an indoor place has no floor of its cell nor an object's floor under it.
    /// </summary>
    public static bool TryUnder(ref Neighbourhood lands, in Place place, float feetZ, float stepUp, out float z, out SurfaceContact floor)
    {
        (LandblockEntry entry, Vector2 p) = (place.Entry, place.Local);
        ObjectSurface? on;
        if (place.CellIndex >= 0)
        {
            CellSurface cell = entry.Cells[place.CellIndex];
            bool found = cell.TrySampleFloor(p.X, p.Y, feetZ, out z, out Vector3 normal);
            var rest = new FloorRest(z, found);
            if (!ObjectFloors.RaiseToRest(cell.Objects, p, feetZ, stepUp, ref rest))
            {
                floor = found ? new SurfaceContact(SurfaceKind.CellFloor, cell.CellId, normal) : default;
                return found;
            }

            (z, on) = (rest.Z, cell.Objects[rest.Object]);
        }
        else
        {
            float terrainZ = entry.Terrain.SampleZUnchecked(p.X, p.Y);
            ObjectHit ground = ObjectQueries.GroundOutdoors(ref lands, entry, p, feetZ, stepUp, terrainZ);
            (z, on) = (ground.GroundZ, ground.Floor);
            if (on is null)
            {
                floor = new SurfaceContact(SurfaceKind.Terrain, WorldFrame.OutdoorCellId(place.X, place.Y, p), entry.Terrain.NormalUnchecked(p.X, p.Y));
                return true;
            }
        }

        floor = new SurfaceContact(SurfaceKind.ObjectFloor, on.ObjectId, on.FloorNormal(p.X, p.Y, z));
        return true;
    }
}
