using AcDream.Core.Dat;
using Environment = AcDream.Core.Dat.Environment;

namespace AcDream.App.Streaming;

/// <summary>
/// One landblock as the background loader hands it to the frame loop: the outdoor heights, the
/// indoor cells, the environments whose cell shapes those cells use, and the landblock's objects as
/// the dat has them (its <see cref="LandBlockInfo"/>, each cell's <see cref="EnvCell.StaticObjects"/>,
/// and the GfxObjs and Setups they name). Nothing here is turned into physics yet;
/// <see cref="DatSurfaces"/> does that on the frame thread, for <see cref="GameWindow"/>.
/// </summary>
/// <param name="LandBlock">The landblock (<c>0xXXYYFFFF</c>): its 9 × 9 height indices.</param>
/// <param name="EnvCells">Its indoor cells (<c>0xXXYYCCCC</c>, CCCC 0x0100..0xFFFD); may be empty. Their <see cref="EnvCell.StaticObjects"/> are the objects standing in them.</param>
/// <param name="Environments">
/// The environments the cells use, by full id (<c>0x0D000000 | EnvCell.EnvironmentId</c>); each
/// holds the <see cref="CellStruct"/>s a cell picks with <see cref="EnvCell.CellStructure"/>.
/// </param>
/// <param name="Info">Its object list (<c>0xXXYYFFFE</c>: <see cref="LandBlockInfo.Objects"/> and <see cref="LandBlockInfo.Buildings"/>, standing outdoors), or null when it has none.</param>
/// <param name="GfxObjs">The GfxObjs (<c>0x01xxxxxx</c>) the objects name, directly or as Setup parts; null for none.</param>
/// <param name="Setups">The Setups (<c>0x02xxxxxx</c>) the objects name; null for none.</param>
public sealed record LoadedLandblock(
    LandBlock LandBlock,
    IReadOnlyList<EnvCell> EnvCells,
    IReadOnlyDictionary<uint, Environment> Environments,
    LandBlockInfo? Info = null,
    IReadOnlyDictionary<uint, GfxObj>? GfxObjs = null,
    IReadOnlyDictionary<uint, Setup>? Setups = null);
