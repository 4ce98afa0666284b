namespace AcDream.Core.Dat;

/// <summary>An environment (dat id <c>0x0D00XXXX</c>): the shared cell shapes that <see cref="EnvCell"/>s place.</summary>
public sealed class Environment
{
    /// <summary>The environment's full dat id, <c>0x0D000000 | EnvCell.EnvironmentId</c>.</summary>
    public uint Id { get; set; }

    /// <summary>Cell shapes by index (<see cref="EnvCell.CellStructure"/>).</summary>
    public Dictionary<uint, CellStruct> Cells { get; set; } = [];
}
