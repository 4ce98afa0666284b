using AcDream.App.Fixtures;
using AcDream.App.Streaming;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using Environment = AcDream.Core.Dat.Environment;

namespace AcDream.App.World;

/// <summary>
/// The default scene's world: synthetic hills on every landblock, flat at the cottage's floor height
/// (94 m) around Holtburg's two buildings, one rock needle too steep to climb, and the 22 real
/// Holtburg cells in landblock 0xA9B4. No real heights are public, so the heights are made up; the
/// height table is non-linear like the game's.
/// </summary>
internal sealed class HoltburgWorld : ILandblockSource
{
    /// <summary>Holtburg's landblock, the centre of the scene's world frame.</summary>
    public const uint Holtburg = 0xA9B4FFFFu;

    /// <summary>Height (metres) of the flat ground around the buildings: the cottage's floor.</summary>
    public const float FlatZ = 94f;

    /// <summary>Height index whose table entry is <see cref="FlatZ"/>.</summary>
    public const byte FlatIndex = 64;

    /// <summary>Height index of the needle vertex: 326 m, about 230 m above its neighbours.</summary>
    public const byte NeedleIndex = 160;

    /// <summary>The needle's vertex indices in 0xA9B4: at landblock-local (72, 48) m.</summary>
    public static readonly (int X, int Y) NeedleVertex = (3, 2);

    private static readonly int HoltburgX = CellIds.LandblockX(Holtburg), HoltburgY = CellIds.LandblockY(Holtburg);

    private readonly List<CellFixtureReader.FixtureCell> _cells;
    private readonly Dictionary<uint, Environment> _environments = [];

    public HoltburgWorld()
    {
        _cells = HoltburgFixtures.ReadAll();
        foreach (CellFixtureReader.FixtureCell cell in _cells)
        {
            // The fixtures carry no environment ids: each cell gets its own synthetic environment,
            // numbered as the cell (0x0D000145 for 0xA9B40145). No CellIds helper gives a cell number.
            ushort environmentId = CellIds.CellNumber(cell.CellId);
            cell.EnvCell.EnvironmentId = environmentId;
            cell.EnvCell.CellStructure = 0;
            _environments.Add(0x0D000000u | environmentId, new Environment { Id = 0x0D000000u | environmentId, Cells = { [0] = cell.CellStruct } });
        }

        HeightTable = BuildHeightTable();
        CellSurfaces = _cells.ConvertAll(c => new CellSurface(c.CellId, c.EnvCell, c.CellStruct));
    }

    /// <summary>The region's height table: 256 heights in metres, finer steps near 94 m, coarser away from it.</summary>
    public float[] HeightTable { get; }

    /// <summary>The real cells of 0xA9B4, ascending id.</summary>
    public IReadOnlyList<CellFixtureReader.FixtureCell> Cells => _cells;

    /// <summary>The engine's surfaces of <see cref="Cells"/>, in the same order: what the engine is given for 0xA9B4 (built once).</summary>
    public IReadOnlyList<CellSurface> CellSurfaces { get; }

    /// <summary>Table entry i = 94 + 0.5·d + 0.02·d·|d| metres with d = i − 64: monotonic, 94 m at 64.</summary>
    public static float[] BuildHeightTable()
    {
        var table = new float[256];
        for (int i = 0; i < table.Length; i++)
        {
            float d = i - FlatIndex;
            table[i] = FlatZ + (0.5f * d) + (0.02f * d * MathF.Abs(d));
        }

        return table;
    }

    /// <summary>The 81 height indices of a landblock, x-major, from one function of the global vertex coordinates, so seams match.</summary>
    public static byte[] Heights(uint landblockId)
    {
        int lbX = CellIds.LandblockX(landblockId), lbY = CellIds.LandblockY(landblockId);
        var heights = new byte[LandBlock.VertexCount];
        for (int x = 0; x < 9; x++)
        {
            for (int y = 0; y < 9; y++)
            {
                heights[(x * 9) + y] = HeightIndex((lbX * 8) + x, (lbY * 8) + y);
            }
        }

        return heights;
    }

    /// <summary>A short name for a Holtburg cell, or null for other cells.</summary>
    public static string? CellName(uint cellId) => cellId switch
    {
        0xA9B40140u => "cottage, raised doorway",
        0xA9B40141u => "cottage, north room",
        0xA9B40142u => "cottage, raised passage",
        0xA9B40143u => "cottage, main room",
        0xA9B40144u => "cottage, doorway to 0x013F",
        0xA9B40145u => "cottage, west door",
        0xA9B40146u => "cottage, cellar shaft",
        0xA9B40147u => "cottage, cellar",
        0xA9B40148u => "cottage, cellar ramp",
        0xA9B40149u => "cottage, cellar end",
        0xA9B4014Au => "cottage, upper opening",
        0xA9B4014Bu => "cottage, upper floor",
        0xA9B4014Cu => "cottage, north-west door",
        0xA9B4014Du => "cottage, upper floor east",
        0xA9B4014Eu => "cottage, upper door",
        0xA9B4014Fu => "cottage, north door",
        0xA9B40170u => "building B, north door",
        0xA9B40171u => "building B, main room",
        0xA9B40172u => "building B, east room",
        0xA9B40173u => "building B, doorway",
        0xA9B40174u => "building B, cellar",
        0xA9B40175u => "building B, cellar shaft",
        _ => null,
    };

    /// <summary>The game-triangle terrain of a landblock, as the engine gets it.</summary>
    public TerrainSurface Terrain(uint landblockId) => new(Heights(landblockId), HeightTable, CellIds.LandblockOf(landblockId));

    /// <inheritdoc />
    public LoadedLandblock Load(uint landblockId)
    {
        uint id = CellIds.LandblockOf(landblockId);
        var landBlock = new LandBlock { Id = id, Height = Heights(id) };
        return id == Holtburg
            ? new LoadedLandblock(landBlock, _cells.ConvertAll(c => c.EnvCell), _environments)
            : new LoadedLandblock(landBlock, [], new Dictionary<uint, Environment>());
    }

    /// <summary>
    /// Height index of global vertex (gx, gy): 64 (94 m) on a rectangle around the buildings
    /// (0xA9B4-local x 96..216 m, y −48..48 m), rolling hills of about ±15 m blending in over 72 m
    /// outside it, and the needle.
    /// </summary>
    private static byte HeightIndex(int gx, int gy)
    {
        if (gx == (HoltburgX * 8) + NeedleVertex.X && gy == (HoltburgY * 8) + NeedleVertex.Y)
        {
            return NeedleIndex;
        }

        // Metres from 0xA9B4's south-west corner.
        double wx = (gx - (HoltburgX * 8)) * 24.0, wy = (gy - (HoltburgY * 8)) * 24.0;
        double dx = Math.Max(0, Math.Max(96 - wx, wx - 216)), dy = Math.Max(0, Math.Max(-48 - wy, wy - 48));
        double t = Math.Clamp(Math.Sqrt((dx * dx) + (dy * dy)) / 72.0, 0, 1);
        double weight = t * t * (3 - (2 * t));
        double hill = (14 * Math.Sin((wx / 70) + 0.3) * Math.Cos(wy / 55))
            + (9 * Math.Sin((wx - (2 * wy)) / 110))
            + (5 * Math.Cos((wx / 33) - (wy / 41)));
        return (byte)Math.Clamp(FlatIndex + (int)Math.Round(weight * hill), 0, 255);
    }
}
