using System.Numerics;

namespace AcDream.Core.Physics.World;

/// <summary>
/// Builds the immutable <see cref="LandblockEntry"/> of a landblock from its terrain, cells and objects,
/// checking every argument first: cells of this landblock, each once, sorted by id; each object in a
/// cell given (or outdoors); building shells marking their cells; outdoor things within
/// <see cref="PhysicsConstants.MaxSeamReach"/> of the landblock. Nothing is published here.
/// </summary>
internal static class LandblockAssembly
{
    /// <summary>The entry of landblock <paramref name="landblockId"/>, or an exception naming what is wrong.</summary>
    /// <exception cref="ArgumentNullException">An argument, a cell or an object is null.</exception>
    /// <exception cref="ArgumentException">See <c>PhysicsEngine.AddLandblock</c>; an object's own fault is an <see cref="ObjectRefusedException"/>.</exception>
    public static LandblockEntry Build(uint landblockId, TerrainSurface terrain, IReadOnlyList<CellSurface> cells, IReadOnlyList<ObjectSurface> objects)
    {
        ArgumentNullException.ThrowIfNull(objects);
        CellIds.ValidateLandblockId(landblockId, nameof(landblockId));
        ArgumentNullException.ThrowIfNull(terrain);
        ArgumentNullException.ThrowIfNull(cells);
        uint prefix = CellIds.Prefix(landblockId);
        if (terrain.LandblockId is uint terrainId && CellIds.Prefix(terrainId) != prefix)
        {
            throw new ArgumentException(
                $"landblock 0x{prefix | 0xFFFF:X8}: the terrain was built for landblock 0x{terrainId:X8}.", nameof(terrain));
        }

        CellSurface[] sorted = SortedCells(prefix, cells);
        int[] outdoorIndex = [];
        ObjectSurface[] outdoor = objects.Count == 0 ? [] : PlaceObjects(prefix, sorted, objects, out outdoorIndex);
        var entry = new LandblockEntry(CellIds.LandblockX(landblockId), CellIds.LandblockY(landblockId), terrain, sorted, outdoor);
        CheckSeamReach(prefix, entry, outdoorIndex);
        return entry;
    }

    private static CellSurface[] SortedCells(uint prefix, IReadOnlyList<CellSurface> cells)
    {
        var sorted = new CellSurface[cells.Count];
        for (int i = 0; i < sorted.Length; i++)
        {
            CellSurface cell = cells[i] ?? throw new ArgumentNullException(nameof(cells), $"landblock 0x{prefix | 0xFFFF:X8}: cells[{i}] is null.");
            if (CellIds.Prefix(cell.CellId) != prefix)
            {
                throw new ArgumentException(
                    $"landblock 0x{prefix | 0xFFFF:X8}: cell 0x{cell.CellId:X8} belongs to another landblock.", nameof(cells));
            }

            sorted[i] = cell;
        }

        Array.Sort(sorted, static (a, b) => a.CellId.CompareTo(b.CellId));
        for (int i = 1; i < sorted.Length; i++)
        {
            if (sorted[i].CellId == sorted[i - 1].CellId)
            {
                throw new ArgumentException(
                    $"landblock 0x{prefix | 0xFFFF:X8}: cell 0x{sorted[i].CellId:X8} is listed twice.", nameof(cells));
            }
        }

        return sorted;
    }

    /// <summary>
    /// Refuses a landblock whose outdoor objects or building cells reach more than
    /// <see cref="PhysicsConstants.MaxSeamReach"/> past its edges (neighbours look only that far), naming the first.
    /// </summary>
    private static void CheckSeamReach(uint prefix, LandblockEntry entry, int[] outdoorIndex)
    {
        const float reach = PhysicsConstants.MaxSeamReach, far = PhysicsConstants.LandblockSize + PhysicsConstants.MaxSeamReach;
        if (entry.OutdoorMin.X >= -reach && entry.OutdoorMin.Y >= -reach && entry.OutdoorMax.X <= far && entry.OutdoorMax.Y <= far)
        {
            return;
        }

        for (int i = 0; i < entry.OutdoorObjects.Length; i++)
        {
            ObjectSurface o = entry.OutdoorObjects[i];
            if (Beyond(ObjectBox.GridBounds(o)) is string beyond)
            {
                throw new ObjectRefusedException(
                    $"landblock 0x{prefix | 0xFFFF:X8}: object 0x{o.ObjectId:X8} (objects[{outdoorIndex[i]}]) {beyond}",
                    "objects", outdoorIndex[i], o.ObjectId, ObjectRule.ReachesPastSeam);
            }
        }

        for (int i = 0; i < entry.Cells.Length; i++)
        {
            if (entry.MetOutdoors[i] && Beyond((entry.CellWallBounds[i].Min, entry.CellWallBounds[i].Max)) is string beyond)
            {
                throw new ArgumentException($"landblock 0x{prefix | 0xFFFF:X8}: cell 0x{entry.Cells[i].CellId:X8}'s walls {beyond}", "cells");
            }
        }

        static string? Beyond((Vector2 Min, Vector2 Max) box) =>
            !(box.Min.X >= -reach && box.Min.Y >= -reach && box.Max.X <= far && box.Max.Y <= far) && box.Min.X <= box.Max.X
                ? $"reach from {box.Min} to {box.Max}, more than {reach} m past the landblock (0..192 m); " +
                  "outdoor objects and the walls of buildings may reach at most PhysicsConstants.MaxSeamReach past its edges."
                : null;
    }

    /// <summary>
    /// Puts each indoor object into (a copy of) its cell in <paramref name="sorted"/>, marks the cells of
    /// buildings with shells, and returns the outdoor objects (and, for each, its index in <paramref name="objects"/>).
    /// </summary>
    private static ObjectSurface[] PlaceObjects(uint prefix, CellSurface[] sorted, IReadOnlyList<ObjectSurface> objects, out int[] outdoorIndex)
    {
        var outdoor = new List<ObjectSurface>();
        var indices = new List<int>();
        var inCell = new List<ObjectSurface>?[sorted.Length];
        var shelled = new bool[sorted.Length];
        for (int i = 0; i < objects.Count; i++)
        {
            ObjectSurface o = objects[i] ?? throw new ArgumentNullException(nameof(objects), $"landblock 0x{prefix | 0xFFFF:X8}: objects[{i}] is null.");
            if (o.CellId == 0)
            {
                outdoor.Add(o);
                indices.Add(i);
                foreach (uint door in o.DoorCellIds)
                {
                    Shell(IndexOf(i, o, door, "its door cell", ObjectRule.DoorCellNotGiven));
                }
            }
            else
            {
                (inCell[IndexOf(i, o, o.CellId, "its cell", ObjectRule.CellNotGiven)] ??= []).Add(o);
            }
        }

        for (int c = 0; c < sorted.Length; c++)
        {
            if (inCell[c] is not null || shelled[c])
            {
                sorted[c] = sorted[c].WithObjects(inCell[c]?.ToArray() ?? [], shelled[c]);
            }
        }

        if (outdoor.Count > PhysicsConstants.MaxOutdoorObjects)
        {
            throw new ArgumentException(
                $"landblock 0x{prefix | 0xFFFF:X8}: {outdoor.Count} objects outdoors; at most {PhysicsConstants.MaxOutdoorObjects} are supported.", nameof(objects));
        }

        outdoorIndex = [.. indices];
        return [.. outdoor];

        int IndexOf(int i, ObjectSurface o, uint cellId, string what, ObjectRule rule)
        {
            int index = Array.FindIndex(sorted, c => c.CellId == cellId);
            return index >= 0 ? index : throw new ObjectRefusedException(
                $"landblock 0x{prefix | 0xFFFF:X8}: object 0x{o.ObjectId:X8} (objects[{i}]): {what} 0x{cellId:X8} is not among the cells given.",
                nameof(objects), i, o.ObjectId, rule);
        }

        void Shell(int door)
        {
            // The building: every cell reached from its door through portals between cells.
            var open = new Stack<int>([door]);
            while (open.TryPop(out int c))
            {
                if (shelled[c])
                {
                    continue;
                }

                shelled[c] = true;
                foreach (CellPortalInfo portal in sorted[c].Portals)
                {
                    int next = Array.FindIndex(sorted, s => s.CellId == portal.TargetCellId);
                    if (next >= 0 && !shelled[next])
                    {
                        open.Push(next);
                    }
                }
            }
        }
    }
}
