using AcDream.App.Fixtures;
using AcDream.Core.Dat;

namespace QuickStart;

/// <summary>
/// Landblock 0xA9B4 (Holtburg) as the game's dat holds it: its <see cref="LandBlock"/> (heights), the region's height
/// table, its <see cref="EnvCell"/>s with their <see cref="CellStruct"/>s, its <see cref="LandBlockInfo"/> (buildings) and
/// the <see cref="GfxObj"/>s they place. A client reads these from its dat files; here they come from the project's
/// fixtures (the real cells and objects; flat terrain at 94 m, the real heights not being public).
/// </summary>
internal sealed class HoltburgDat
{
    public required LandBlock LandBlock { get; init; }

    public required float[] HeightTable { get; init; }

    public required List<EnvCell> EnvCells { get; init; }

    public required Dictionary<uint, CellStruct> CellStructs { get; init; }

    public required LandBlockInfo LandBlockInfo { get; init; }

    public required Dictionary<uint, GfxObj> GfxObjs { get; init; }

    public Dictionary<uint, Setup> Setups { get; } = [];

    /// <summary>The CellStruct an EnvCell names (its environment's).</summary>
    public CellStruct CellStructOf(EnvCell cell) => CellStructs[cell.Id];

    /// <summary>Reads the fixtures copied beside the program.</summary>
    public static HoltburgDat Read()
    {
        string folder = Path.Combine(AppContext.BaseDirectory, "Fixtures");
        List<CellFixtureReader.FixtureCell> cells = Directory.GetFiles(Path.Combine(folder, "holtburg-cells"), "*.json").Order()
            .Select(path => CellFixtureReader.Read(File.ReadAllText(path), path)).ToList();
        Dictionary<uint, GfxObj> gfxObjs = Directory.GetFiles(Path.Combine(folder, "objects"), "0x*.json")
            .Select(path => ObjectFixtureReader.Read(File.ReadAllText(path), path)).ToDictionary(o => o.Id);

        // The cellar stairs stand in the cellars as their static objects.
        foreach ((uint cellId, GfxObj stair, Stab placement) in ObjectPlacements.CellarStairs())
        {
            gfxObjs[stair.Id] = stair;
            cells.Single(c => c.CellId == cellId).EnvCell.StaticObjects.Add(placement);
        }

        return new HoltburgDat
        {
            LandBlock = new LandBlock { Id = 0xA9B4FFFFu, Height = new byte[LandBlock.VertexCount] }, // every vertex at height index 0
            HeightTable = Enumerable.Repeat(94f, 256).ToArray(),
            EnvCells = cells.Select(c => c.EnvCell).ToList(),
            CellStructs = cells.ToDictionary(c => c.EnvCell.Id, c => c.CellStruct),
            LandBlockInfo = ObjectPlacements.HoltburgInfo(),
            GfxObjs = gfxObjs,
        };
    }
}
