using AcDream.Core.Dat;
using AcDream.Core.Physics;
using Environment = AcDream.Core.Dat.Environment;

namespace AcDream.App.Streaming;

/// <summary>
/// Turns a loaded landblock's dat data into the engine's surfaces: its <see cref="TerrainSurface"/>
/// (the game's triangles, from the region's height table and the landblock id), one
/// <see cref="CellSurface"/> per cell whose environment and cell struct resolve, and one
/// <see cref="ObjectSurface"/> per object of its <see cref="LoadedLandblock.Info"/> and of its
/// built cells' <see cref="EnvCell.StaticObjects"/>. A cell or an object that cannot be built is
/// skipped with a warning naming it and the reason; an object standing in a skipped cell is skipped
/// with it.
/// </summary>
internal sealed class DatSurfaces
{
    private readonly float[] _heightTable;
    private readonly Action<string> _log;

    /// <summary>Converts with the region's height table.</summary>
    /// <param name="heightTable">The region's 256 heights in metres (<c>LandHeightTable</c>); copied.</param>
    /// <param name="log">Receives the warnings, one line each.</param>
    /// <exception cref="ArgumentException">The table does not have 256 finite entries.</exception>
    public DatSurfaces(float[] heightTable, Action<string> log)
    {
        ArgumentNullException.ThrowIfNull(heightTable);
        if (heightTable.Length != 256 || Array.Exists(heightTable, h => !float.IsFinite(h)))
        {
            throw new ArgumentException($"the height table must have 256 finite heights; it has {heightTable.Length} entries.", nameof(heightTable));
        }

        _heightTable = (float[])heightTable.Clone();
        _log = log;
    }

    /// <summary>The landblock's terrain.</summary>
    /// <param name="landblockId">The landblock, <c>0xXXYYFFFF</c>.</param>
    /// <param name="loaded">What the source returned for it.</param>
    /// <param name="error">Null, or why there is no terrain.</param>
    /// <returns>Null, with the reason, when the source returned another landblock or its heights build no terrain.</returns>
    public TerrainSurface? Terrain(uint landblockId, LoadedLandblock loaded, out string? error)
    {
        error = null;
        if (loaded.LandBlock is null || CellIds.LandblockOf(loaded.LandBlock.Id) != landblockId)
        {
            error = $"the source returned landblock 0x{loaded.LandBlock?.Id ?? 0:X8}";
            return null;
        }

        try
        {
            return new TerrainSurface(loaded.LandBlock.Height, _heightTable, landblockId);
        }
        catch (ArgumentException e)
        {
            error = e.Message;
            return null;
        }
    }

    /// <summary>The landblock's cells that can be built, in the order of <see cref="LoadedLandblock.EnvCells"/>; each other one is skipped with a warning.</summary>
    /// <param name="landblockId">The landblock, <c>0xXXYYFFFF</c>.</param>
    /// <param name="loaded">What the source returned for it.</param>
    public List<CellSurface> Cells(uint landblockId, LoadedLandblock loaded)
    {
        var cells = new List<CellSurface>();
        var ids = new HashSet<uint>();
        foreach (EnvCell? envCell in loaded.EnvCells ?? [])
        {
            string? problem = CellProblem(landblockId, envCell, loaded.Environments, ids, out CellSurface? cell);
            if (problem is null)
            {
                cells.Add(cell!);
                ids.Add(cell!.CellId);
            }
            else
            {
                _log($"landblock 0x{landblockId:X8}: cell 0x{envCell?.Id ?? 0:X8} skipped: {problem}");
            }
        }

        return cells;
    }

    /// <summary>
    /// The landblock's objects, built one by one (each through <see cref="ObjectSurface.FromLandblock"/>
    /// with that object alone) so a bad one is reported and skipped, as a bad cell is: the
    /// <see cref="LandBlockInfo"/>'s objects and buildings, then the static objects of each built
    /// cell. (A building whose door cell is not registered is refused by the engine, by name, and
    /// <see cref="GameWindow.ApplyLoadedTerrainLocked"/> drops it.)
    /// </summary>
    /// <param name="landblockId">The landblock, <c>0xXXYYFFFF</c>.</param>
    /// <param name="loaded">What the source returned for it.</param>
    /// <param name="cells">Its cells that were built (<see cref="Cells"/>); the objects of the others are skipped.</param>
    public List<ObjectSurface> Objects(uint landblockId, LoadedLandblock loaded, IEnumerable<CellSurface> cells)
    {
        var cellIds = cells.Select(c => c.CellId).ToHashSet();
        var result = new List<ObjectSurface>();
        IReadOnlyDictionary<uint, GfxObj> gfxObjs = loaded.GfxObjs ?? new Dictionary<uint, GfxObj>();
        IReadOnlyDictionary<uint, Setup> setups = loaded.Setups ?? new Dictionary<uint, Setup>();
        void Build(string what, LandBlockInfo? info, EnvCell? cell)
        {
            try
            {
                result.AddRange(ObjectSurface.FromLandblock(landblockId, info, cell is null ? [] : [cell], gfxObjs, setups));
            }
            catch (ArgumentException e)
            {
                _log($"landblock 0x{landblockId:X8}: {what} skipped: {e.Message}");
            }
        }

        if (loaded.Info is LandBlockInfo info)
        {
            if (info.Id != 0 && CellIds.LandblockOf(info.Id) != landblockId)
            {
                _log($"landblock 0x{landblockId:X8}: its object list 0x{info.Id:X8} skipped: it belongs to another landblock");
            }
            else
            {
                for (int i = 0; i < (info.Objects?.Count ?? 0); i++)
                {
                    Stab stab = info.Objects![i];
                    Build($"object {i} (0x{stab?.Id ?? 0:X8})", new LandBlockInfo { Id = info.Id, Objects = [stab!] }, null);
                }

                for (int i = 0; i < (info.Buildings?.Count ?? 0); i++)
                {
                    BuildingInfo building = info.Buildings![i];
                    string what = $"building {i} (0x{building?.ModelId ?? 0:X8})";
                    Build(what, new LandBlockInfo { Id = info.Id, Buildings = [building!] }, null);
                }
            }
        }

        foreach (EnvCell? envCell in loaded.EnvCells ?? [])
        {
            if (envCell?.StaticObjects is not { Count: > 0 } statics)
            {
                continue;
            }

            if (!cellIds.Contains(envCell.Id))
            {
                _log($"landblock 0x{landblockId:X8}: the {statics.Count} object(s) of cell 0x{envCell.Id:X8} skipped with their cell");
                continue;
            }

            for (int i = 0; i < statics.Count; i++)
            {
                Build($"object {i} (0x{statics[i]?.Id ?? 0:X8}) of cell 0x{envCell.Id:X8}", null, new EnvCell { Id = envCell.Id, StaticObjects = [statics[i]] });
            }
        }

        return result;
    }

    private static string? CellProblem(uint landblockId, EnvCell? envCell, IReadOnlyDictionary<uint, Environment>? environments, HashSet<uint> ids, out CellSurface? cell)
    {
        cell = null;
        if (envCell is null)
        {
            return "the cell is null";
        }

        if (CellIds.LandblockOf(envCell.Id) != CellIds.LandblockOf(landblockId))
        {
            return "the cell belongs to another landblock";
        }

        if (ids.Contains(envCell.Id))
        {
            return "the cell is listed twice";
        }

        uint environmentId = 0x0D000000u | envCell.EnvironmentId;
        if (environments is null || !environments.TryGetValue(environmentId, out Environment? environment) || environment is null)
        {
            return $"environment 0x{environmentId:X8} is missing";
        }

        if (environment.Cells is null || !environment.Cells.TryGetValue(envCell.CellStructure, out CellStruct? cellStruct) || cellStruct is null)
        {
            return $"cell struct {envCell.CellStructure} is missing from environment 0x{environmentId:X8}";
        }

        try
        {
            cell = new CellSurface(envCell.Id, envCell, cellStruct);
            return null;
        }
        catch (ArgumentException e)
        {
            return e.Message;
        }
    }
}
